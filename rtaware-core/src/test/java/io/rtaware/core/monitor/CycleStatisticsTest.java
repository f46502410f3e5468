package io.rtaware.core.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertSame;

import io.rtaware.core.report.Percentiles;
import org.HdrHistogram.AbstractHistogram;
import org.HdrHistogram.Histogram;
import org.HdrHistogram.IntCountsHistogram;
import java.util.Arrays;
import java.util.function.Function;
import java.util.function.ObjLongConsumer;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

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

    /** One of the two series recorded in batches: how a value is noted, and how the report reads the series. */
    private record Series(String name, ObjLongConsumer<CycleStatistics> note,
                          Function<CycleStatistics, Percentiles> report) {
        @Override
        public String toString() {
            return name;
        }
    }

    static Stream<Series> series() {
        return Stream.of(new Series("lateness", CycleStatistics::released, CycleStatistics::latenessUs),
                new Series("execution time", CycleStatistics::cycleEnded, CycleStatistics::execUs));
    }

    @ParameterizedTest
    @MethodSource("series")
    void valuesRecordedInBatchesReportEveryValueWhateverTheCountAndTwiceTheSame(Series series) {
        for (int spread : new int[] {0, 1, CycleStatistics.RECORD_BATCH - 1, CycleStatistics.RECORD_BATCH + 3}) {
            for (int count : new int[] {1, CycleStatistics.RECORD_BATCH - 1, CycleStatistics.RECORD_BATCH,
                    3 * CycleStatistics.RECENT_EXEC_CYCLES + 7}) {
                assertReportsEveryValue(series, new CycleStatistics(spread), count);
            }
        }
    }

    private static void assertReportsEveryValue(Series series, CycleStatistics statistics, int count) {
        Histogram reference = new Histogram(1, 3_600_000_000_000L, 2);
        long maxNs = 0;
        double sumNs = 0;
        for (int i = 0; i < count; i++) {
            long ns = 1_000 + 37L * i * i;
            series.note().accept(statistics, ns);
            reference.recordValue(ns);
            maxNs = Math.max(maxNs, ns);
            sumNs += ns;
        }
        Percentiles expected = Percentiles.ofNanos(reference, maxNs, sumNs);
        assertEquals(expected, series.report().apply(statistics),
                series + ", " + count + " values: the ones still waiting in the ring are recorded before the report");
        assertEquals(expected, series.report().apply(statistics),
                series + ", " + count + " values: a second report counts none twice");
        series.note().accept(statistics, 2_000);
        reference.recordValue(2_000);
        assertEquals(Percentiles.ofNanos(reference, Math.max(maxNs, 2_000), sumNs + 2_000),
                series.report().apply(statistics),
                series + ", " + count + " values: a value noted after a report is recorded once");
    }

    /**
     * Tasks released together flush their batches in different cycles: task i records its waiting
     * values (both series) when the count of cycles ended is i modulo the batch, so no cycle
     * records every task's batch.
     */
    @Test
    void eachTaskFlushesItsBatchAtItsOwnPhase() {
        int batch = CycleStatistics.RECORD_BATCH;
        CycleStatistics task3 = new CycleStatistics(3);
        CycleStatistics task19 = new CycleStatistics(batch + 3);
        CycleStatistics task0 = new CycleStatistics(0);
        long[] waiting3 = new long[3 * batch + 1];
        for (int count = 1; count <= 3 * batch; count++) {
            for (CycleStatistics statistics : new CycleStatistics[] {task3, task19, task0}) {
                statistics.released(1_000 + count);
                statistics.cycleEnded(2_000 + count);
            }
            waiting3[count] = task3.latenessWaiting();
            assertEquals(waiting3[count], task3.execWaiting(), "both series flush together");
            assertEquals(waiting3[count], task19.latenessWaiting(), "the phase is the index modulo the batch");
            boolean flushed3 = waiting3[count] == 0;
            boolean flushed0 = task0.latenessWaiting() == 0 && task0.execWaiting() == 0;
            assertEquals(count % batch == 3, flushed3, "task 3 after " + count + " cycles");
            assertEquals(count % batch == 0, flushed0, "task 0 after " + count + " cycles");
        }
        assertEquals(2, waiting3[2], "before the first flush every value waits");
        assertEquals(batch - 1, waiting3[batch + 2], "a full batch minus one waits just before the next flush");
        assertEquals(1, waiting3[batch + 4]);
    }

    /**
     * Releases noted without their cycles' ends (the phase is counted in cycles ended) are recorded
     * once their ring is nearly full, before any is overwritten.
     */
    @Test
    void latenessNotedAloneIsRecordedBeforeItsRingFills() {
        CycleStatistics statistics = new CycleStatistics(5);
        long most = 0;
        for (int i = 0; i < 10 * CycleStatistics.WAITING_CAPACITY; i++) {
            statistics.released(1_000 + i);
            most = Math.max(most, statistics.latenessWaiting());
        }
        assertEquals(StatisticsTable.RECORD_WHEN_WAITING - 1, most,
                "recorded when the count waiting reaches " + StatisticsTable.RECORD_WHEN_WAITING);
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

    /**
     * Tasks of one table keep their execution times apart: each ring of recent ones (laid out by
     * position, the tasks side by side) gives its task's exact live p99 and histogram, through
     * more cycles than a ring holds, with the tasks' cycles interleaved as a drain runs them.
     */
    @Test
    void tasksSharingATableKeepTheirOwnExecutionTimes() {
        int tasks = 3;
        StatisticsTable table = new StatisticsTable(tasks);
        CycleStatistics[] statistics = new CycleStatistics[tasks];
        Histogram[] reference = new Histogram[tasks];
        long[][] latest = new long[tasks][CycleStatistics.RECENT_EXEC_CYCLES];
        long[] maxNs = new long[tasks];
        double[] sumNs = new double[tasks];
        for (int t = 0; t < tasks; t++) {
            statistics[t] = new CycleStatistics(table, t, t);
            reference[t] = new Histogram(1, 3_600_000_000_000L, 2);
        }
        int cycles = 2 * CycleStatistics.RECENT_EXEC_CYCLES + 5;
        for (int n = 0; n < cycles; n++) {
            for (int t = 0; t < tasks; t++) {
                long ns = (t + 1) * 100_000L + 13L * ((n * 7919L + t) % 1000);
                statistics[t].cycleEnded(ns);
                reference[t].recordValue(ns);
                latest[t][n % CycleStatistics.RECENT_EXEC_CYCLES] = ns;
                maxNs[t] = Math.max(maxNs[t], ns);
                sumNs[t] += ns;
            }
        }
        for (int t = 0; t < tasks; t++) {
            long[] sorted = latest[t].clone();
            Arrays.sort(sorted);
            assertEquals(sorted[(int) Math.ceil(0.99 * sorted.length) - 1], statistics[t].counters().recentExecP99Ns(),
                    "task " + t + ": the exact p99 of its own latest " + CycleStatistics.RECENT_EXEC_CYCLES);
            assertEquals(Percentiles.ofNanos(reference[t], maxNs[t], sumNs[t]), statistics[t].execUs(),
                    "task " + t + ": every execution time of its own, and only those");
        }
    }
}
