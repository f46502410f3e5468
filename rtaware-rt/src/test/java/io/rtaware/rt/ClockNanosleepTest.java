package io.rtaware.rt;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import com.sun.jna.Platform;
import io.rtaware.core.testing.ReleasePathStrings;
import io.rtaware.core.time.MonotonicSleeper;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The libc sleep, for real: never early, and nothing allocated per call. */
class ClockNanosleepTest {

    /** A task thread sleeps with it every cycle: no string constant may wait to be resolved there by a C2 compile. */
    @Test
    void itsStringConstantsAreLoadedOnlyWhileItIsBuilt() throws IOException {
        assertEquals(List.of(), ReleasePathStrings.unresolvedAfterBuilding(ClockNanosleep.class));
    }


    @Test
    void onLinuxItSleepsUntilTheAbsoluteInstantAndNeverWakesBeforeIt() {
        assumeTrue(Platform.isLinux(), "clock_nanosleep is bound on Linux only");
        MonotonicSleeper sleeper = ClockNanosleep.load().orElseThrow();
        for (int i = 0; i < 5; i++) {
            long target = System.nanoTime() + 2_000_000;
            sleeper.sleepUntil(target);
            // CLOCK_MONOTONIC is System.nanoTime()'s clock, and an absolute sleep ends at or after
            // its instant (a signal could end it early; none is sent here).
            assertTrue(System.nanoTime() >= target, "woke before the instant asked for");
        }
    }

    @Test
    void sleepsAllocateNothing() {
        assumeTrue(Platform.isLinux(), "clock_nanosleep is bound on Linux only");
        MonotonicSleeper sleeper = ClockNanosleep.load().orElseThrow();
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long id = Thread.currentThread().getId();
        for (int i = 0; i < 20_000; i++) {
            sleeper.sleepUntil(System.nanoTime() - 1); // warm-up: compiled paths, the thread's buffer
        }
        long before = threads.getThreadAllocatedBytes(id);
        for (int i = 0; i < 20_000; i++) {
            sleeper.sleepUntil(System.nanoTime() - 1);
            sleeper.sleepUntil(1); // an instant long past
        }
        long after = threads.getThreadAllocatedBytes(id);
        assertEquals(0, after - before, "bytes allocated by 40 000 sleeps");
    }
}
