package io.rtaware.ros2msg.statistics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.monitor.CycleOutcome;
import io.rtaware.ros2msg.value.MetricsMessage;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The windows, the metrics and the rules of publication on stepped world time: every record is
 * handed over by the test at a time it chooses, every value is worked out by hand.
 */
class TimingStatisticsTest {

    private static final long MS = 1_000_000L;
    private static final long S = 1_000_000_000L;
    private static final long EPOCH = 1_764_000_000L * S;

    /** What one message said. */
    private record Published(String source, String metric, String unit, long startNs, long stopNs, double average,
                             double min, double max, double stddev, double count, long worldStopNs) {
    }

    private final List<Published> out = new ArrayList<>();
    private final MetricsSink sink = (m, worldStopNs) -> {
        assertEquals(5, m.count());
        assertEquals(List.of(MetricsMessage.AVERAGE, MetricsMessage.MINIMUM, MetricsMessage.MAXIMUM,
                MetricsMessage.STDDEV, MetricsMessage.SAMPLE_COUNT), List.of(m.dataType(0), m.dataType(1),
                m.dataType(2), m.dataType(3), m.dataType(4)), "ROS 2's order of data points");
        out.add(new Published(m.measurementSourceName.toString(), m.metricsSource.toString(), m.unit.toString(),
                m.windowStartNs, m.windowStopNs, m.data(0), m.data(1), m.data(2), m.data(3), m.data(4), worldStopNs));
    };

    /** Task 0 "sensor" (no inputs) commits key 0 "scan"; task 1 "planner" reads it; key 1 "plan" is not followed. */
    private TimingStatistics statistics(long originNs) {
        return new TimingStatistics(List.of("sensor", "planner"), List.of(List.of(), List.of("scan", "plan")),
                Arrays.asList("scan", null), originNs, EPOCH, S, sink);
    }

    private Published find(String source, String metric, long stopNs) {
        return out.stream().filter(p -> p.source.equals(source) && p.metric.equals(metric) && p.stopNs == stopNs)
                .findFirst().orElseThrow(() -> new AssertionError("no " + source + " " + metric + " to " + stopNs
                        + " in " + out));
    }

    private static void assertStatistics(Published p, double average, double min, double max, double stddev,
                                         long count) {
        assertEquals(count, p.count, "count of " + p);
        assertEquals(average, p.average, 1e-12, "average of " + p);
        assertEquals(min, p.min, 1e-12, "min of " + p);
        assertEquals(max, p.max, 1e-12, "max of " + p);
        assertEquals(stddev, p.stddev, 1e-12, "stddev of " + p);
    }

    private static void assertEmpty(Published p) {
        assertEquals(0, p.count, "count of " + p);
        assertTrue(Double.isNaN(p.average) && Double.isNaN(p.min) && Double.isNaN(p.max) && Double.isNaN(p.stddev),
                "no samples: NaN, as ROS 2 publishes it: " + p);
    }

    /** The sensor's cycle k (release k * 100 ms, 2 ms late, 3 ms long) and its commit of generation k + 1. */
    private static void sensorCycle(TimingStatistics s, int k) throws Exception {
        long release = k * 100 * MS;
        s.commit(0, k + 1, release + 5 * MS);
        s.cycle(0, CycleOutcome.OK, release, release + 2 * MS, release + 5 * MS, null);
    }

    @Test
    void aWindowsMetricsPerTaskAndKeyAreTheRos2Statistics() throws Exception {
        TimingStatistics s = statistics(0);
        for (int k = 0; k < 10; k++) {
            sensorCycle(s, k); // scan committed at 5, 105, ..., 905 ms
        }
        // planner: released at 50, 250, 450, 650, 850 ms, starts 1 ms later, runs 4 ms, reads the newest scan
        s.cycle(1, CycleOutcome.OK, 50 * MS, 51 * MS, 55 * MS, new long[] {1, 7});
        s.cycle(1, CycleOutcome.MISS, 250 * MS, 251 * MS, 255 * MS, new long[] {3, 7});
        s.cycle(1, CycleOutcome.ERROR, 450 * MS, 451 * MS, 455 * MS, new long[] {5, 7});
        s.cycle(1, CycleOutcome.OK, 650 * MS, 651 * MS, 655 * MS, new long[] {7, 7});
        s.cycle(1, CycleOutcome.STALE, 850 * MS, 851 * MS, 855 * MS, new long[] {9, 7});
        // again at 950 ms (a continuous release), holding the same scan: not a receipt
        s.cycle(1, CycleOutcome.STALE, 950 * MS, 950 * MS, 952 * MS, new long[] {9, 7});
        assertEquals(0, s.finish(999 * MS), "the first window is not over at 999 ms");
        assertEquals(10, s.finish(S), "4 metrics of 2 tasks and 2 of the one key followed");
        assertEquals(List.of("sensor release_lateness", "sensor execution_time", "sensor input_age",
                "sensor deadline_misses", "planner release_lateness", "planner execution_time", "planner input_age",
                "planner deadline_misses", "scan message_period", "scan message_age"),
                out.stream().map(p -> p.source + " " + p.metric).toList().subList(0, 10));

        long stop = EPOCH + S;
        Published first = find("sensor", "release_lateness", stop);
        assertEquals(EPOCH, first.startNs, "window_start: world time 0 plus the stamp offset");
        assertEquals(S, first.worldStopNs);
        assertEquals("ms", first.unit);
        assertStatistics(first, 2, 2, 2, 0, 10);
        assertStatistics(find("sensor", "execution_time", stop), 3, 3, 3, 0, 10);
        assertEmpty(find("sensor", "input_age", stop));
        assertStatistics(find("sensor", "deadline_misses", stop), 0, 0, 0, 0, 10);
        assertEquals("count", find("sensor", "deadline_misses", stop).unit);

        // lateness 1 ms five times and 0 once; execution 4 ms five times and 2 ms once
        assertStatistics(find("planner", "release_lateness", stop), 5.0 / 6, 0, 1, Math.sqrt(5.0 / 36), 6);
        assertStatistics(find("planner", "execution_time", stop), 22.0 / 6, 2, 4, Math.sqrt(20.0 / 36), 6);
        // ages at the start: 51 - 5, 251 - 205, ... = 46 ms five times; 950 - 805 = 145 ms once
        assertStatistics(find("planner", "input_age", stop), (5 * 46 + 145) / 6.0, 46, 145,
                Math.sqrt(5.0 / 36 * 99 * 99), 6);
        // releases met or missed: OK, MISS, (ERROR: neither), OK, STALE, STALE
        assertStatistics(find("planner", "deadline_misses", stop), 0.2, 0, 1, 0.4, 5);

        // nine periods of 100 ms (the first commit has none); five receipts 46 ms old
        assertStatistics(find("scan", "message_period", stop), 100, 100, 100, 0, 9);
        assertStatistics(find("scan", "message_age", stop), 46, 46, 46, 0, 5);
        assertEquals(0, s.lateRecords());
        assertEquals(0, s.unmatchedAges());
    }

    @Test
    void aWindowIsPublishedOneDrainAfterEveryActiveTaskHasPassedItsEnd() throws Exception {
        TimingStatistics s = statistics(0);
        sensorCycle(s, 9);
        s.cycle(1, CycleOutcome.OK, 900 * MS, 910 * MS, 920 * MS, new long[] {10, 0});
        assertEquals(0, s.drained(Long.MIN_VALUE));
        sensorCycle(s, 10); // the sensor has passed 1 s; the planner has not
        assertEquals(0, s.drained(Long.MIN_VALUE));
        s.cycle(1, CycleOutcome.OK, 1100 * MS, 1101 * MS, 1102 * MS, new long[] {11, 0});
        assertEquals(0, s.drained(Long.MIN_VALUE), "both have passed 1 s, seen in this drain: published at the next");
        assertEquals(10, s.drained(Long.MIN_VALUE));
        assertEquals(1, s.windowsPublished());
        assertStatistics(find("planner", "execution_time", EPOCH + S), 10, 10, 10, 0, 1);
        assertStatistics(find("scan", "message_age", EPOCH + S), 5, 5, 5, 0, 1);
        assertEquals(S, s.nextWindowStartNs());
    }

    @Test
    void aQuietTaskHoldsAWindowBackForTheGraceOnly() throws Exception {
        TimingStatistics s = statistics(0);
        s.cycle(1, CycleOutcome.OK, 0, 0, 10 * MS, new long[] {0, 0}); // the planner reports once, then never
        for (int k = 0; k <= 11; k++) {
            sensorCycle(s, k);
            s.drained(Long.MIN_VALUE);
            assertEquals(0, s.windowsPublished(), "at " + (k * 100 + 5) + " ms: the planner held the window back");
        }
        sensorCycle(s, 12); // 1205 ms: the planner has been quiet for more than the grace since 1105 ms
        s.drained(Long.MIN_VALUE);
        assertEquals(1, s.windowsPublished());
        sensorCycle(s, 13);
        s.drained(Long.MIN_VALUE);
        sensorCycle(s, 20); // 2005 ms
        s.drained(Long.MIN_VALUE);
        assertEquals(1, s.windowsPublished());
        s.drained(Long.MIN_VALUE);
        assertEquals(2, s.windowsPublished(), "without the quiet planner, the sensor alone decides, one drain later");
    }

    @Test
    void aDrainThatRanAheadOnOneRingWaitsForTheOthersOfTheNextDrain() throws Exception {
        // A recorder's pass drains the key's ring, then the sensor's, while the sensor runs on:
        // the commits seen stop at 1.505 s, the cycles at 3.405 s.
        TimingStatistics s = statistics(0);
        for (int k = 0; k <= 15; k++) {
            s.commit(0, k + 1, k * 100 * MS + 5 * MS);
        }
        for (int k = 0; k <= 34; k++) {
            s.cycle(0, CycleOutcome.OK, k * 100 * MS, k * 100 * MS + 2 * MS, k * 100 * MS + 5 * MS, null);
        }
        assertEquals(0, s.drained(Long.MIN_VALUE), "the sensor is past 3 s, but that is judged at this drain");
        for (int k = 16; k <= 34; k++) { // the next pass: the rest of the commits
            s.commit(0, k + 1, k * 100 * MS + 5 * MS);
        }
        assertEquals(30, s.drained(Long.MIN_VALUE), "three windows, the sensor alone being active");
        assertStatistics(find("scan", "message_period", EPOCH + 2 * S), 100, 100, 100, 0, 10);
        assertStatistics(find("scan", "message_period", EPOCH + 3 * S), 100, 100, 100, 0, 10);
        assertEquals(0, s.lateRecords());
    }

    @Test
    void theClockPublishesWindowsOfAnIdleMonitorAfterTheGrace() throws Exception {
        TimingStatistics s = statistics(500 * MS);
        assertEquals(0, s.drained(2499 * MS));
        assertEquals(0, s.drained(2500 * MS), "judged now, published at the next drain");
        assertEquals(10, s.drained(2500 * MS), "the window from 0.5 s to 1.5 s, 1 s of grace later");
        assertEmpty(find("sensor", "execution_time", EPOCH + 1500 * MS));
        assertEquals(EPOCH + 500 * MS, out.get(0).startNs);
    }

    @Test
    void aRecordOfAPublishedWindowIsCountedLateAndLeftOut() throws Exception {
        TimingStatistics s = statistics(0);
        s.drained(2 * S);
        s.drained(2 * S);
        assertEquals(1, s.windowsPublished());
        s.cycle(0, CycleOutcome.OK, 990 * MS, 992 * MS, 995 * MS, null);
        s.commit(0, 1, 995 * MS);
        s.skipped(0, 2, 995 * MS);
        s.cycle(0, CycleOutcome.OK, 1000 * MS, 1002 * MS, 1005 * MS, null);
        s.drained(3 * S);
        s.drained(3 * S);
        assertEquals(3, s.lateRecords());
        assertStatistics(find("sensor", "execution_time", EPOCH + 2 * S), 3, 3, 3, 0, 1);
        assertStatistics(find("sensor", "deadline_misses", EPOCH + 2 * S), 0, 0, 0, 0, 1);
    }

    @Test
    void aCycleThatReadACommitNotYetHandedOverWaitsForIt() throws Exception {
        TimingStatistics s = statistics(0);
        s.commit(0, 1, 100 * MS);
        // the planner read generation 2, committed at 300 ms, whose commit arrives after its record
        s.cycle(1, CycleOutcome.OK, 400 * MS, 400 * MS, 410 * MS, new long[] {2, 0});
        s.drained(Long.MIN_VALUE);
        s.commit(0, 2, 300 * MS);
        s.drained(Long.MIN_VALUE);
        s.finish(S);
        assertStatistics(find("planner", "input_age", EPOCH + S), 100, 100, 100, 0, 1);
        assertStatistics(find("scan", "message_age", EPOCH + S), 100, 100, 100, 0, 1);
        assertStatistics(find("scan", "message_period", EPOCH + S), 200, 200, 200, 0, 1);
        assertEquals(0, s.unmatchedAges());
    }

    @Test
    void agesWhoseCommitIsMissingAreCountedNotGuessed() throws Exception {
        TimingStatistics s = statistics(0);
        s.commit(0, 1, 100 * MS);
        s.commit(0, 3, 300 * MS); // generation 2 was dropped: no period for 3
        s.cycle(1, CycleOutcome.OK, 350 * MS, 350 * MS, 360 * MS, new long[] {2, 0}); // held the dropped one
        s.cycle(1, CycleOutcome.OK, 450 * MS, 450 * MS, 460 * MS, new long[] {4, 0}); // its commit never comes
        s.finish(S);
        assertEmpty(find("scan", "message_period", EPOCH + S));
        assertEmpty(find("planner", "input_age", EPOCH + S));
        assertEmpty(find("scan", "message_age", EPOCH + S));
        assertEquals(4, s.unmatchedAges(), "two input ages and two receipts");
    }

    @Test
    void cyclesBeyondTheWaitingRoomAreCountedAsUnmatched() throws Exception {
        TimingStatistics s = statistics(0);
        for (int i = 0; i <= TimingStatistics.PENDING; i++) { // each read a scan whose commit never comes
            s.cycle(1, CycleOutcome.OK, i * MS, i * MS, i * MS + 1, new long[] {i + 1, 0});
        }
        assertEquals(2, s.unmatchedAges(), "the one beyond the room: its input age and its receipt");
        s.finish(S);
        assertEquals(2 * (TimingStatistics.PENDING + 1), s.unmatchedAges(), "and those that waited in vain");
        assertStatistics(find("planner", "execution_time", EPOCH + S), 1e-6, 1e-6, 1e-6, 0,
                TimingStatistics.PENDING + 1);
    }

    @Test
    void skippedReleasesAreMissesAndAFarRecordPublishesTheWindowsBeforeIt() throws Exception {
        TimingStatistics s = statistics(0);
        s.cycle(0, CycleOutcome.MISS, 0, 0, 350 * MS, null);
        s.skipped(0, 3, 350 * MS);
        s.cycle(0, CycleOutcome.OK, 400 * MS, 400 * MS, 401 * MS, null);
        s.cycle(0, CycleOutcome.OK, 5 * S, 5 * S, 5 * S + MS, null); // after a stall: windows 0 and 1 go out now
        assertEquals(2, s.windowsPublished());
        assertStatistics(find("sensor", "deadline_misses", EPOCH + S), 0.8, 0, 1, 0.4, 5);
        assertEmpty(find("sensor", "deadline_misses", EPOCH + 2 * S));
        s.finish(Long.MIN_VALUE);
        assertEquals(5, s.windowsPublished(), "up to 5 s; the window holding 5.001 s is not over");
    }

    @Test
    void aWindowAfterAPublishedOneStartsEmpty() throws Exception {
        TimingStatistics s = statistics(0);
        s.cycle(0, CycleOutcome.OK, 0, 0, 7 * MS, null);
        s.cycle(0, CycleOutcome.OK, 1100 * MS, 1100 * MS, 1101 * MS, null);
        s.finish(2 * S);
        assertStatistics(find("sensor", "execution_time", EPOCH + S), 7, 7, 7, 0, 1);
        assertStatistics(find("sensor", "execution_time", EPOCH + 2 * S), 1, 1, 1, 0, 1);
    }
}
