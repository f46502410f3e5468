package io.rtaware.bench.compare;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import io.rtaware.core.testing.ReleasePathStrings;
import java.io.IOException;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The comparison's bookkeeping, on made-up times (no threads, no clock). */
class ReleaseStatsTest {

    /**
     * Its {@code onRun}, and the rtaware rows' listener that calls it, run on the task threads
     * inside the measured windows, whose allocation the comparison counts as the framework's: no
     * string constant may wait to be resolved there.
     */
    @Test
    void itsStringConstantsAreLoadedOnlyWhileItIsBuilt() throws IOException, ClassNotFoundException {
        assertEquals(List.of(), ReleasePathStrings.unresolvedAfterBuilding(ReleaseStats.class));
        assertEquals(List.of(), ReleasePathStrings.unresolvedAfterBuilding(
                Class.forName(RtawareSegment.class.getName() + "$StatsListener")));
    }


    private static final long PERIOD = 10_000_000;

    @Test
    void latenessIsStartMinusIntendedReleaseNotMinusPreviousStart() {
        ReleaseStats s = new ReleaseStats(PERIOD);
        // A 3 ms stall delays release 1; release 2 is on time again.
        s.onRun(0, 50_000, 1_000_000);
        s.onRun(PERIOD, PERIOD + 3_000_000, PERIOD + 4_000_000);
        s.onRun(2 * PERIOD, 2 * PERIOD + 50_000, 2 * PERIOD + 1_000_000);
        assertEquals(3, s.releases());
        assertEquals(3_000_000, s.maxLatenessNs());
        assertEquals(3_000_000, s.latenessNs().getMaxValue(), 3_000_000 * 0.01);
        assertEquals(50_000, s.latenessNs().getValueAtPercentile(50), 50_000 * 0.01);
        assertEquals(0, s.misses());
        assertEquals(0, s.bursts());
    }

    @Test
    void aRunStartingLessThanHalfAPeriodAfterThePreviousIsABurst() {
        ReleaseStats s = new ReleaseStats(PERIOD);
        // Release 0 overruns to 25 ms; a fixed-rate executor then runs releases 1 and 2 back to back.
        s.onRun(0, 0, 25_000_000);
        s.onRun(PERIOD, 25_000_000, 25_100_000);
        s.onRun(2 * PERIOD, 25_100_000, 25_200_000);
        s.onRun(3 * PERIOD, 3 * PERIOD, 3 * PERIOD + 100_000);
        assertEquals(4, s.releases());
        assertEquals(2, s.bursts(), "releases 1 and 2 started 25 ms and 0.1 ms after the previous start");
        assertEquals(2, s.misses(), "release 0 ended at 25 ms > 10 ms; release 1 ended at 25.1 ms > 20 ms");
    }

    @Test
    void exactlyHalfAPeriodApartIsNotABurst() {
        ReleaseStats s = new ReleaseStats(PERIOD);
        s.onRun(0, 0, 1);
        s.onRun(PERIOD, PERIOD / 2, PERIOD / 2 + 1);
        assertEquals(0, s.bursts());
    }

    @Test
    void finishingExactlyAtTheDeadlineIsNotAMiss() {
        ReleaseStats s = new ReleaseStats(PERIOD);
        s.onRun(0, 0, PERIOD);
        s.onRun(PERIOD, PERIOD, 2 * PERIOD + 1);
        assertEquals(1, s.misses());
    }

    @Test
    void skippedReleasesAreReleasesAndMisses() {
        ReleaseStats s = new ReleaseStats(PERIOD);
        s.onRun(0, 0, 35_000_000);
        s.onSkipped(3, 35_000_000);
        s.onRun(4 * PERIOD, 4 * PERIOD, 4 * PERIOD + 1);
        assertEquals(5, s.releases());
        assertEquals(4, s.misses());
        assertEquals(0, s.bursts());
    }

    @Test
    void onlyReleasesInsideTheWindowCountButBurstsSeeThePreviousRunOutsideIt() {
        ReleaseStats s = new ReleaseStats(PERIOD);
        s.reset();
        s.openWindow(PERIOD, 3 * PERIOD);
        s.onRun(0, 0, 15_000_000);
        s.onSkipped(1, 5_000_000);
        s.onRun(PERIOD, 15_000_000, 15_000_001);
        s.onRun(2 * PERIOD, 2 * PERIOD, 2 * PERIOD + 1);
        s.onRun(3 * PERIOD, 3 * PERIOD, 3 * PERIOD + 1);
        assertEquals(2, s.releases());
        assertEquals(0, s.misses());
        assertEquals(0, s.bursts());
        assertEquals(5_000_000, s.maxLatenessNs());
    }

    @Test
    void resetClearsEverything() {
        ReleaseStats s = new ReleaseStats(PERIOD);
        s.onRun(0, 0, 2 * PERIOD);
        s.onRun(PERIOD, 2 * PERIOD, 2 * PERIOD);
        s.reset();
        s.openWindow(Long.MIN_VALUE, Long.MAX_VALUE);
        assertEquals(0, s.releases());
        assertEquals(0, s.misses());
        assertEquals(0, s.maxLatenessNs());
        assertEquals(0, s.latenessNs().getTotalCount());
        assertEquals(0, s.threadId());
        s.onRun(0, 1, 2);
        assertEquals(0, s.bursts(), "the previous start is forgotten");
        assertEquals(Thread.currentThread().getId(), s.threadId());
    }

    @Test
    void afterAResetNothingCountsUntilTheWindowOpens() {
        ReleaseStats s = new ReleaseStats(PERIOD);
        s.reset();
        s.onRun(0, 3_000_000, 25_000_000);
        s.onSkipped(1, 25_000_000);
        assertEquals(0, s.releases(), "a slow start-up before the window is not counted");
        assertEquals(0, s.misses());
        s.openWindow(3 * PERIOD, 5 * PERIOD);
        s.onRun(3 * PERIOD, 3 * PERIOD + 1, 3 * PERIOD + 2);
        assertEquals(1, s.releases());
    }

    @Test
    void aPeriodMustBePositive() {
        assertThrows(IllegalArgumentException.class, () -> new ReleaseStats(0));
    }
}
