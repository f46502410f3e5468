package io.rtaware.core.monitor;

import io.rtaware.core.report.Percentiles;
import java.lang.invoke.VarHandle;
import java.util.Arrays;
import org.HdrHistogram.AbstractHistogram;
import org.HdrHistogram.Histogram;
import org.HdrHistogram.IntCountsHistogram;

/**
 * One task's counts and distributions: what the report and the live counters say about it.
 *
 * <p>Writers: the task's cycle (its own thread, or whichever pool worker runs it) records every
 * cycle; the watchdog adds misses it detects, and any thread may count a listener fault. Counts
 * written by the cycle alone are published with ordered stores (no read-modify-write on the hot
 * path); misses, which two threads add, are atomic. The counters, running sums and the lateness
 * values waiting for their histogram are this task's column of its monitor's
 * {@link StatisticsTable}, accessed through a {@link VarHandle}, rather than fields of this object
 * or an object each: with thousands of tasks a pool worker finds every task's state out of its
 * caches, each object touched per cycle is one more cache miss (issue 16's profile at 10 000
 * tasks), and in the table the tasks released together share cache lines (issue 36).
 *
 * <p>Memory (issue 16: 10 000 tasks in the launcher's 512 MB heap): two histograms per task,
 * lateness and execution time, recorded by the cycle and read only after the task's cycles have
 * stopped, plus the task's column of the table, which holds a ring of the latest
 * {@value #RECENT_EXEC_CYCLES} execution times for the live p99. The histograms keep
 * HdrHistogram's two significant digits with a resolution of
 * {@value #LOWEST_DISCERNIBLE_NS} ns below 2 us, which is the resolution a 1 ns histogram has
 * from 1 us up anyway (the report rounds to 0.1 us). Their range ends at {@value
 * #HIGHEST_TRACKABLE_NS} ns (about 17 s, longer than any deadline a controller is built for):
 * a larger value is counted there, the exact maximum is kept beside, and a percentile that falls
 * into that top bucket reads as the maximum ({@link Percentiles#ofNanos}). Counts are 32-bit
 * ({@link IntCountsHistogram}, half the bytes); a bucket cannot overflow while the histogram's
 * total stays below {@link Integer#MAX_VALUE}, so at that total (after 2^31 - 1 cycles, 24.8 days
 * of a 1 kHz task) the histogram is copied once into a 64-bit one: the only allocation on the
 * cycle's path, once per task and run.
 */
final class CycleStatistics {

    /** Top of the histograms' range: 2^34 ns, about 17.2 s; larger values are clamped to it. */
    static final long HIGHEST_TRACKABLE_NS = 1L << 34;
    /** Resolution below 2 us: 8 ns (a 1 ns histogram of two digits has 8 ns buckets from 1 us up). */
    static final long LOWEST_DISCERNIBLE_NS = 8;
    private static final int SIGNIFICANT_DIGITS = 2;
    /** The live p99 covers the latest this many cycles (all of them before that many have run). */
    static final int RECENT_EXEC_CYCLES = 256;
    /**
     * Lateness and execution times wait in small rings and go into their histograms this many at
     * a time when the task's cycle records them: with thousands of tasks a histogram is out of
     * the caches at every cycle, and one touch per batch instead of one per cycle is the saving
     * (issue 16's profiles at 10 000 tasks: recording into the two histograms took a third to a
     * half of the workers' samples, most of them the first read of the histogram's minimum and
     * maximum). Execution times wait in the ring of recent ones (written anyway for the live
     * p99), lateness in the task's {@link #WAITING_CAPACITY} waiting values of the
     * {@link StatisticsTable}. Divides both. Each group of {@link StatisticsTable#TASKS_PER_LINE}
     * tasks flushes at its own phase of the batch ({@link #flushPhaseOf}): tasks released
     * together would otherwise all record a whole batch in the same cycle, and with 10 000 tasks
     * in phase every 16th period took 7.5 ms to release instead of 2.7 ms (issue 16: the longest
     * release of each period, period by period, showed the spikes 16 periods apart, and they set
     * every task's p99). The pool's tasks are recorded by a {@link StatisticsRecorder} instead.
     */
    static final int RECORD_BATCH = 16;
    /**
     * Lateness values that may wait per task: room for a {@link StatisticsRecorder} to fall
     * {@link StatisticsTable#RECORD_WHEN_WAITING} cycles behind before the cycle records them
     * itself, and one batch more.
     */
    static final int WAITING_CAPACITY = 64;
    /**
     * Heap besides HdrHistogram's footprint estimate of the histograms and the task's column of
     * its {@link StatisticsTable}: this object, what the histograms' objects take beyond that
     * estimate (80 bytes each), and the table object and array headers of statistics with a
     * table of their own (about 470 bytes, which the tasks of a monitor share), as
     * {@code MonitorFootprintTest} measures them with the JVM's allocation counter.
     */
    private static final long FIELDS_BYTES = 640;

    private static final VarHandle LONGS = StatisticsTable.LONGS;

    /**
     * The counters and sums, in the table's arrays at {@link #slot}: written with ordered stores
     * by the cycle's thread, atomic adds where two threads write (misses, listener errors), read
     * with acquiring reads by anyone.
     */
    private final StatisticsTable table;
    private final int slot;

    /**
     * Statistics of their own (a table of one task), that flush their batches when the count of
     * values noted is a multiple of {@link #RECORD_BATCH}.
     */
    CycleStatistics() {
        this(0);
    }

    /**
     * Statistics of their own (a table of one task).
     *
     * @param spreadIndex the batches of values go into the histograms when the count of cycles
     *     ended is {@code spreadIndex} modulo {@link #RECORD_BATCH} (the first batch is then shorter)
     */
    CycleStatistics(int spreadIndex) {
        this(new StatisticsTable(1), 0, spreadIndex);
    }

    /**
     * One task's column of a monitor's table.
     *
     * @param table the table of every task of the monitor
     * @param slot the task's column
     * @param spreadIndex spreads the batches of many tasks over the cycles: the task's waiting
     *     values go into its histograms when the count of cycles ended is {@code spreadIndex}
     *     modulo {@link #RECORD_BATCH} ({@link #flushPhaseOf} of the task's index serves)
     */
    CycleStatistics(StatisticsTable table, int slot, int spreadIndex) {
        this.table = table;
        this.slot = slot;
        table.flushPhase[slot] = Math.floorMod(spreadIndex, RECORD_BATCH);
    }

    /**
     * @param taskIndex a task's index
     * @return the spread index for the task's statistics: the same for the
     *     {@link StatisticsTable#TASKS_PER_LINE} tasks whose values share cache lines, so they
     *     flush in the same cycle, one after the other, and read the same waiting lines
     */
    static int flushPhaseOf(int taskIndex) {
        return taskIndex / StatisticsTable.TASKS_PER_LINE;
    }

    /**
     * @return the heap bytes one task's statistics take: its two histograms as HdrHistogram
     *     estimates their footprint, its column of the table (the lateness values waiting to be
     *     recorded and the ring of recent execution times included) and this object
     */
    static long estimatedHeapBytes() {
        return 2 * newHistogram().getEstimatedFootprintInBytes() + StatisticsTable.bytesPerTask() + FIELDS_BYTES;
    }

    /** @return HdrHistogram's footprint estimate of the two histograms this instance holds now */
    long histogramFootprintBytes() {
        return table.latenessHistograms[slot].getEstimatedFootprintInBytes()
                + table.execHistograms[slot].getEstimatedFootprintInBytes();
    }

    /**
     * A release came due and its cycle starts now (cycle's thread). A task's own cycle does the
     * same through the table ({@link TaskRuntime} holds it), so as not to touch this object.
     */
    void released(long latenessNs) {
        if (table.released(slot, latenessNs)) {
            table.tryRecordWaiting(slot);
        }
    }

    /**
     * A cycle ended after {@code execNs} of world time (cycle's thread). A task's own cycle does
     * the same through the table ({@link TaskRuntime} holds it), so as not to touch this object.
     */
    void cycleEnded(long execNs) {
        if (table.cycleEnded(slot, execNs)) {
            table.tryRecordWaiting(slot);
        }
    }

    /** @return lateness values noted but not yet in their histogram */
    long latenessWaiting() {
        return (long) LONGS.getAcquire(table.latenessCount, slot)
                - (long) LONGS.getAcquire(table.latenessRecordedCount, slot);
    }

    /** @return execution times noted but not yet in their histogram */
    long execWaiting() {
        return (long) LONGS.getAcquire(table.recentExecCount, slot)
                - (long) LONGS.getAcquire(table.execRecordedCount, slot);
    }

    /** {@code count} releases were skipped, each a release and a miss (cycle's thread). */
    void skipped(long count) {
        StatisticsTable t = table;
        LONGS.setRelease(t.releases, slot, t.releases[slot] + count);
        LONGS.setRelease(t.skipped, slot, t.skipped[slot] + count);
        long unused = (long) LONGS.getAndAdd(t.misses, slot, count);
    }

    /** A cycle missed its deadline (cycle's thread or watchdog). */
    void missed() {
        long unused = (long) LONGS.getAndAdd(table.misses, slot, 1L);
    }

    void staleRun() {
        LONGS.setRelease(table.staleRuns, slot, table.staleRuns[slot] + 1);
    }

    void error() {
        LONGS.setRelease(table.errors, slot, table.errors[slot] + 1);
    }

    void expiredRead() {
        LONGS.setRelease(table.expiredReads, slot, table.expiredReads[slot] + 1);
    }

    /** A listener failed on one of this task's events (any thread). */
    void listenerError() {
        long unused = (long) LONGS.getAndAdd(table.listenerErrors, slot, 1L);
    }

    long releases() {
        return (long) LONGS.getAcquire(table.releases, slot);
    }

    long runs() {
        return (long) LONGS.getAcquire(table.runs, slot);
    }

    long misses() {
        return (long) LONGS.getAcquire(table.misses, slot);
    }

    long skippedReleases() {
        return (long) LONGS.getAcquire(table.skipped, slot);
    }

    long staleRuns() {
        return (long) LONGS.getAcquire(table.staleRuns, slot);
    }

    long errors() {
        return (long) LONGS.getAcquire(table.errors, slot);
    }

    long expiredReads() {
        return (long) LONGS.getAcquire(table.expiredReads, slot);
    }

    long listenerErrors() {
        return (long) LONGS.getAcquire(table.listenerErrors, slot);
    }

    /** Live counters, safe at any time from any thread; allocates (not for the cycle's thread). */
    TaskCounters counters() {
        return new TaskCounters(releases(), runs(), misses(), skippedReleases(), staleRuns(), errors(),
                expiredReads(), recentExecP99Ns());
    }

    /**
     * The 99th percentile of the latest {@value #RECENT_EXEC_CYCLES} cycles' execution times (of
     * all cycles before that many have run), exact: with n values sorted, the ceil(0.99 n)-th,
     * as HdrHistogram ranks them; 0 before the first cycle. A cycle that ends during the read
     * may replace the oldest value read, which a live figure can afford.
     */
    private long recentExecP99Ns() {
        long count = (long) LONGS.getAcquire(table.recentExecCount, slot);
        int n = (int) Math.min(count, RECENT_EXEC_CYCLES);
        if (n == 0) {
            return 0;
        }
        long[] latest = new long[n];
        for (int i = 0; i < n; i++) {
            latest[i] = (long) LONGS.getAcquire(table.recentExecNs, table.ringIndex(slot, i, RECENT_EXEC_CYCLES));
        }
        Arrays.sort(latest);
        return latest[(int) Math.ceil(0.99 * n) - 1];
    }

    /** @return execution times over the run; call only after the task's cycles have stopped */
    Percentiles execUs() {
        table.recordWaiting(slot);
        return Percentiles.ofNanos(table.execHistograms[slot], table.execMaxNs[slot], table.execSumNs[slot]);
    }

    /** @return lateness over the run; call only after the task's cycles have stopped */
    Percentiles latenessUs() {
        table.recordWaiting(slot);
        return Percentiles.ofNanos(table.latenessHistograms[slot], table.latenessMaxNs[slot], table.latenessSumNs[slot]);
    }

    /** @return an empty histogram of a task's lateness or execution times */
    static AbstractHistogram newHistogram() {
        return new IntCountsHistogram(LOWEST_DISCERNIBLE_NS, HIGHEST_TRACKABLE_NS, SIGNIFICANT_DIGITS);
    }

    /**
     * Records a value, first copying a 32-bit histogram whose total has reached
     * {@link Integer#MAX_VALUE} into a 64-bit one (below that total no bucket can overflow).
     *
     * @return the histogram to keep: the same one, or its 64-bit copy
     */
    static AbstractHistogram record(AbstractHistogram histogram, long valueNs) {
        AbstractHistogram target = histogram;
        if (histogram instanceof IntCountsHistogram && histogram.getTotalCount() >= Integer.MAX_VALUE) {
            target = new Histogram(histogram);
            target.add(histogram);
        }
        target.recordValue(Math.min(Math.max(valueNs, 1), HIGHEST_TRACKABLE_NS));
        return target;
    }
}
