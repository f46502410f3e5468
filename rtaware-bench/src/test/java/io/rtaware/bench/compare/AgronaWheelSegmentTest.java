package io.rtaware.bench.compare;

import static org.junit.jupiter.api.Assertions.assertEquals;

import io.rtaware.bench.load.BusyWork;
import org.junit.jupiter.api.Test;

/**
 * The agrona-wheel row's loop on a manual clock: when it polls, how long it parks, and the
 * lateness it records (the run's start against the task's grid point), with the skip rule.
 */
class AgronaWheelSegmentTest {

    private static final BusyWork WORK = BusyWork.calibrate();
    private static final long PERIOD = 10_000_000;
    private static final long TICK = 1L << AgronaWheelSegment.TICK_SHIFT;

    private long now;

    private AgronaWheelSegment.WheelLoop loop(long firstNs, ReleaseStats stats) {
        GridTask task = new GridTask(firstNs, PERIOD, 0, WORK, stats, () -> now);
        return new AgronaWheelSegment.WheelLoop(new GridTask[] {task}, 0, 16, () -> now);
    }

    /**
     * Polls at each tick boundary after the clock up to {@code untilNs}, as the loop wakes when
     * nothing expires, and again at once after each expiry.
     */
    private void pollEachTick(AgronaWheelSegment.WheelLoop loop, long untilNs) {
        for (now = (now / TICK + 1) * TICK; now <= untilNs; now += TICK) {
            while (loop.pollOnce() == 0) {
                // polls again at once after an expiry, as the thread's loop does
            }
        }
        now -= TICK;
    }

    @Test
    void aReleaseInsideATickRunsAtTheTicksEndAndIsLateByTheRestOfTheTick() {
        ReleaseStats stats = new ReleaseStats(PERIOD);
        AgronaWheelSegment.WheelLoop loop = loop(300_000, stats);

        assertEquals(TICK, loop.pollOnce(), "nothing due at 0: park until the end of tick 0");
        assertEquals(0, stats.releases());

        now = TICK;
        assertEquals(0, loop.pollOnce(), "a timer expired: poll again at once");
        assertEquals(1, stats.releases());
        assertEquals(TICK - 300_000, stats.maxLatenessNs(), "start (the tick's end) minus the grid point");
        assertEquals(TICK, loop.pollOnce(), "tick 1 has nothing: park to its end");

        // The next release is on the grid, 10.3 ms, in tick 9; the loop reaches its end at 10 ticks.
        pollEachTick(loop, 10 * TICK);
        assertEquals(2, stats.releases());
        assertEquals(0, stats.misses());
        assertEquals(TICK - 300_000, stats.maxLatenessNs(), "the second run was 10 ticks - 10.3 ms = 0.19 ms late");
        assertEquals(1, stats.latenessNs().getCountBetweenValues(185_000, 186_999), "10 485 760 - 10 300 000 ns");
    }

    @Test
    void aRunPastLaterReleasesSkipsToTheNextGridPointAndCountsTheSkippedAsMisses() {
        ReleaseStats stats = new ReleaseStats(PERIOD);
        AgronaWheelSegment.WheelLoop loop = loop(0, stats);

        now = 25_000_000; // the loop's thread was held 25 ms
        assertEquals(0, loop.pollOnce());
        assertEquals(25_000_000, stats.maxLatenessNs());
        assertEquals(3, stats.releases(), "the run of 0 ms, and 10 ms and 20 ms skipped");
        assertEquals(3, stats.misses(), "the late run ended past its deadline, and two skipped");
        assertEquals(0, loop.pollOnce(), "the wheel's tick is behind the clock: poll again without parking");

        pollEachTick(loop, 28 * TICK);
        assertEquals(3, stats.releases(), "30 ms lies in tick 28, not reached before 29 ticks (30.4 ms)");
        pollEachTick(loop, 29 * TICK);
        assertEquals(4, stats.releases(), "the next run is the release of 30 ms");
        assertEquals(1, stats.latenessNs().getCountBetweenValues(405_000, 410_999),
                "run at the end of its tick: 29 ticks - 30 ms = 408 704 ns");
    }

    @Test
    void theWheelSpansTheLongestPeriodInAPowerOfTwoOfTicks() {
        assertEquals(16, AgronaWheelSegment.ticksPerWheel(10_000_000), "10 ms is 9.5 ticks; at least 16");
        assertEquals(16, AgronaWheelSegment.ticksPerWheel(16 * TICK));
        assertEquals(32, AgronaWheelSegment.ticksPerWheel(16 * TICK + 1));
        assertEquals(128, AgronaWheelSegment.ticksPerWheel(100_000_000), "100 ms is 95.4 ticks");
    }
}
