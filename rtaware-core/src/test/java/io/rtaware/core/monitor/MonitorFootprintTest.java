package io.rtaware.core.monitor;

import static io.rtaware.core.Ms.ms;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import io.rtaware.core.FnTask;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.time.ManualClock;
import java.lang.management.ManagementFactory;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * {@link Monitor#estimatedHeapBytesPerTask()} is what the monitor really allocates per task, as
 * the JVM counts it: commands refuse task sets with it, so it must neither fall short (an
 * OutOfMemoryError later) nor overstate much (a task set that fits refused).
 */
class MonitorFootprintTest {

    private static final int TASKS = 256;
    /** The estimate may exceed the measured allocation by this factor at most. */
    private static final double MAX_OVERSTATEMENT = 1.25;

    private static com.sun.management.ThreadMXBean threads() {
        java.lang.management.ThreadMXBean plain = ManagementFactory.getThreadMXBean();
        assumeTrue(plain instanceof com.sun.management.ThreadMXBean, "needs com.sun.management.ThreadMXBean");
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) plain;
        assumeTrue(threads.isThreadAllocatedMemorySupported(), "thread allocation counting is supported");
        threads.setThreadAllocatedMemoryEnabled(true);
        return threads;
    }

    static Stream<ExecutorKind> executors() {
        return Stream.of(ExecutorKind.threaded(), ExecutorKind.pooled(2, ExecutorKind.PoolOrder.EARLIEST_DEADLINE_FIRST));
    }

    /**
     * Bytes this thread allocates to build and start a monitor of {@code tasks} periodic tasks;
     * the tasks themselves (bodies, names, schedule) are made before counting, as they are the
     * user's data.
     */
    private static long buildAndStartBytes(int tasks, ExecutorKind kind) {
        com.sun.management.ThreadMXBean threads = threads();
        long tid = Thread.currentThread().getId();
        FnTask[] bodies = new FnTask[tasks];
        String[] names = new String[tasks];
        Schedule schedule = Schedule.periodic(ms(10));
        for (int i = 0; i < tasks; i++) {
            bodies[i] = FnTask.of(now -> { });
            names[i] = "task-" + i;
        }
        ManualClock clock = new ManualClock();
        long before = threads.getThreadAllocatedBytes(tid);
        Monitor.Builder builder = Monitor.builder(clock).executor(kind);
        for (int i = 0; i < tasks; i++) {
            builder.task(names[i], schedule, bodies[i]);
        }
        Monitor monitor = builder.build();
        monitor.start();
        long after = threads.getThreadAllocatedBytes(tid);
        monitor.stop();
        return after - before;
    }

    @ParameterizedTest
    @MethodSource("executors")
    void estimatePerTaskMatchesWhatBuildingAndStartingATaskAllocates(ExecutorKind kind) {
        buildAndStartBytes(TASKS, kind); // loads and compiles what the measured runs use
        long perTask = (buildAndStartBytes(2 * TASKS, kind) - buildAndStartBytes(TASKS, kind)) / TASKS;
        long estimate = Monitor.estimatedHeapBytesPerTask();
        System.out.printf("%s: %d bytes allocated per task, estimate %d%n", kind, perTask, estimate);
        assertTrue(estimate >= perTask, "the estimate " + estimate + " covers the " + perTask + " bytes measured");
        assertTrue(estimate <= MAX_OVERSTATEMENT * perTask,
                "the estimate " + estimate + " is within " + MAX_OVERSTATEMENT + "x of the " + perTask + " bytes measured");
    }

    @Test
    void statisticsEstimateIsWhatOneInstanceAllocates() {
        com.sun.management.ThreadMXBean threads = threads();
        long tid = Thread.currentThread().getId();
        new CycleStatistics();
        long before = threads.getThreadAllocatedBytes(tid);
        CycleStatistics statistics = new CycleStatistics();
        long allocated = threads.getThreadAllocatedBytes(tid) - before;
        long estimate = CycleStatistics.estimatedHeapBytes();
        assertTrue(estimate >= allocated && estimate <= allocated + 1024,
                "estimate " + estimate + " bytes, allocated " + allocated);
        long ringBytes = CycleStatistics.RECENT_EXEC_CYCLES * Long.BYTES;
        assertTrue(statistics.histogramFootprintBytes() + ringBytes <= allocated,
                "HdrHistogram's footprint of the histograms built, " + statistics.histogramFootprintBytes()
                        + " bytes, plus the ring are part of the " + allocated + " allocated");
        assertEquals(2 * 13_824, statistics.histogramFootprintBytes(),
                "two 32-bit histograms of 8 ns to 2^34 ns at 2 digits: 13.5 KB each (1 ns to 1 h at 64 bits was 37 KB)");
    }
}
