package io.rtaware.core.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertSame;

import io.rtaware.core.report.Percentiles;
import org.HdrHistogram.AbstractHistogram;
import org.HdrHistogram.Histogram;
import org.HdrHistogram.IntCountsHistogram;
import org.junit.jupiter.api.Test;

/** The smaller per-task histograms report what the 1 ns to 1 h ones did. */
class CycleStatisticsTest {

    @Test
    void microsecondValuesReportAsWithOneNanosecondResolution() {
        CycleStatistics statistics = new CycleStatistics();
        Histogram reference = new Histogram(1, 3_600_000_000_000L, 2);
        long maxNs = 0;
        double sumNs = 0;
        for (long ns = 1_000; ns <= 20_000_000; ns = ns * 101 / 100 + 7) {
            statistics.released(ns);
            reference.recordValue(ns);
            maxNs = Math.max(maxNs, ns);
            sumNs += ns;
        }
        assertEquals(Percentiles.ofNanos(reference, maxNs, sumNs), statistics.latenessUs(),
                "from 1 us up the buckets are the same as a 1 ns histogram's");
    }

    @Test
    void latenessRecordedInBatchesReportsEveryReleaseWhateverTheCountAndTwiceTheSame() {
        for (int releases : new int[] {1, CycleStatistics.RECORD_BATCH - 1, CycleStatistics.RECORD_BATCH,
                5 * CycleStatistics.RECORD_BATCH + 3}) {
            CycleStatistics statistics = new CycleStatistics();
            Histogram reference = new Histogram(1, 3_600_000_000_000L, 2);
            long maxNs = 0;
            double sumNs = 0;
            for (int i = 0; i < releases; i++) {
                long ns = 2_000 + 53L * i * i;
                statistics.released(ns);
                reference.recordValue(ns);
                maxNs = Math.max(maxNs, ns);
                sumNs += ns;
            }
            Percentiles expected = Percentiles.ofNanos(reference, maxNs, sumNs);
            assertEquals(expected, statistics.latenessUs(),
                    releases + " releases: the values still waiting in the ring are recorded before the report");
            assertEquals(expected, statistics.latenessUs(), releases + " releases: a second report counts none twice");
            statistics.released(2_000);
            reference.recordValue(2_000);
            assertEquals(Percentiles.ofNanos(reference, maxNs, sumNs + 2_000), statistics.latenessUs(),
                    releases + " releases: a release after a report is recorded once");
        }
    }

    @Test
    void executionTimesRecordedInBatchesReportEveryCycleWhateverTheCount() {
        for (int cycles : new int[] {1, CycleStatistics.RECORD_BATCH - 1, CycleStatistics.RECORD_BATCH,
                3 * CycleStatistics.RECENT_EXEC_CYCLES + 7}) {
            CycleStatistics statistics = new CycleStatistics();
            Histogram reference = new Histogram(1, 3_600_000_000_000L, 2);
            long maxNs = 0;
            double sumNs = 0;
            for (int i = 0; i < cycles; i++) {
                long ns = 1_000 + 37L * i * i;
                statistics.cycleEnded(ns);
                reference.recordValue(ns);
                maxNs = Math.max(maxNs, ns);
                sumNs += ns;
            }
            assertEquals(Percentiles.ofNanos(reference, maxNs, sumNs), statistics.execUs(),
                    cycles + " cycles: the ones still waiting in the ring are recorded before the report");
        }
    }

    @Test
    void aValueBeyondTheRangeKeepsItsExactMaximumAndReadsAsItInTheTopBucket() {
        CycleStatistics statistics = new CycleStatistics();
        long tenMinutesNs = 600_000_000_000L;
        statistics.cycleEnded(tenMinutesNs);
        Percentiles exec = statistics.execUs();
        assertEquals(600_000_000.0, exec.max());
        assertEquals(600_000_000.0, exec.p50(), "the only value is above the range: every percentile is the max");
        assertEquals(600_000_000.0, exec.p999());

        for (int i = 0; i < 499; i++) {
            statistics.cycleEnded(2_000);
        }
        exec = statistics.execUs();
        assertEquals(2.0, exec.p99(), "2000 ns in an 8 ns bucket: 2.0 us");
        assertEquals(600_000_000.0, exec.p999(), "the 500th of 500 values is the clamped one: the max");
    }

    @Test
    void thirtyTwoBitCountsBecomeSixtyFourBitBeforeABucketCanOverflow() {
        AbstractHistogram histogram = new IntCountsHistogram(CycleStatistics.LOWEST_DISCERNIBLE_NS,
                CycleStatistics.HIGHEST_TRACKABLE_NS, 2);
        histogram.recordValueWithCount(5_000, Integer.MAX_VALUE - 1);
        assertSame(histogram, CycleStatistics.record(histogram, 5_000), "below the limit: the same histogram");
        assertEquals(Integer.MAX_VALUE, histogram.getTotalCount());

        AbstractHistogram wide = CycleStatistics.record(histogram, 5_000);
        assertInstanceOf(Histogram.class, wide, "at the limit: a 64-bit copy");
        assertEquals(Integer.MAX_VALUE + 1L, wide.getCountAtValue(5_000), "the copy has every count plus the new one");
        assertSame(wide, CycleStatistics.record(wide, 7_000), "a 64-bit histogram stays");
        assertEquals(Integer.MAX_VALUE + 2L, wide.getTotalCount());
    }
}
