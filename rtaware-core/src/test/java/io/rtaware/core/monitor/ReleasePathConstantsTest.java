package io.rtaware.core.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;

import io.rtaware.core.testing.ReleasePathStrings;
import java.io.IOException;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The classes whose code runs every release, or on a task's thread at its events (the console
 * reporter's listener methods), load string constants only while they are built and started (see
 * {@link ReleasePathStrings}; {@link OffPathText} and {@link ConsoleLines} are where such text
 * lives). The JVMTI probe found the allocation for a worker's class, the system clock's and the
 * bench's listener's.
 */
class ReleasePathConstantsTest {

    @ParameterizedTest
    @ValueSource(classes = {TaskRuntime.class, ReleaseTable.class, CycleStatistics.class,
            StatisticsTable.class, StatisticsRecorder.class, PooledExecutor.class, ThreadedExecutor.class,
            Watchdog.class, ListenerFanOut.class, TaskHeap.class, ParkingClockWaiter.class, InputHandle.class,
            OutputHandle.class, AdaptivePeriodController.class, Executor.class, ConsoleReporter.class,
            io.rtaware.core.time.SystemClock.class, io.rtaware.core.time.ScaledClock.class})
    void stringConstantsAreLoadedOnlyWhileBuilding(Class<?> type) throws IOException {
        assertEquals(List.of(), ReleasePathStrings.unresolvedAfterBuilding(type),
                type.getSimpleName() + ": string constants outside construction");
    }
}
