package io.rtaware.core.monitor;

import io.rtaware.core.report.Percentiles;
import java.util.Arrays;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicLongArray;
import org.HdrHistogram.AbstractHistogram;
import org.HdrHistogram.Histogram;
import org.HdrHistogram.IntCountsHistogram;

/**
 * One task's counts and distributions: what the report and the live counters say about it.
 *
 * <p>Writers: the task's cycle (its own thread, or whichever pool worker runs it) records every
 * cycle; the watchdog adds misses it detects, and any thread may count a listener fault. Counts
 * written by the cycle alone are published with ordered stores (no read-modify-write on the hot
 * path); misses, which two threads add, are atomic.
 *
 * <p>Memory (issue 16: 10 000 tasks in the launcher's 512 MB heap): two histograms per task,
 * lateness and execution time, recorded by the cycle and read only after the task's cycles have
 * stopped, plus a ring of the latest {@value #RECENT_EXEC_CYCLES} execution times for the live
 * p99. The histograms keep HdrHistogram's two significant digits with a resolution of
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
     * Heap of this object besides its histograms and ring: its header and fields, the eight
     * counters, the ring's header and the ring's counter, as {@code
     * CycleStatisticsFootprintTest} measures them with the JVM's allocation counter.
     */
    private static final long FIELDS_BYTES = 512;

    private final AtomicLong releases = new AtomicLong();
    private final AtomicLong runs = new AtomicLong();
    private final AtomicLong misses = new AtomicLong();
    private final AtomicLong skipped = new AtomicLong();
    private final AtomicLong staleRuns = new AtomicLong();
    private final AtomicLong errors = new AtomicLong();
    private final AtomicLong expiredReads = new AtomicLong();
    private final AtomicLong listenerErrors = new AtomicLong();

    private AbstractHistogram latenessNs = newHistogram();
    private long latenessMaxNs;
    private double latenessSumNs;

    private AbstractHistogram execNs = newHistogram();
    private long execMaxNs;
    private double execSumNs;

    /** The latest execution times, slot {@code n % RECENT_EXEC_CYCLES} for the n-th cycle. */
    private final AtomicLongArray recentExecNs = new AtomicLongArray(RECENT_EXEC_CYCLES);
    /** Execution times written to {@link #recentExecNs} so far. */
    private final AtomicLong recentExecCount = new AtomicLong();

    /**
     * @return the heap bytes one instance takes: its two histograms as HdrHistogram estimates
     *     their footprint, the ring of recent execution times, and its fields
     */
    static long estimatedHeapBytes() {
        return 2 * newHistogram().getEstimatedFootprintInBytes() + (long) RECENT_EXEC_CYCLES * Long.BYTES
                + FIELDS_BYTES;
    }

    /** @return HdrHistogram's footprint estimate of the two histograms this instance holds now */
    long histogramFootprintBytes() {
        return latenessNs.getEstimatedFootprintInBytes() + execNs.getEstimatedFootprintInBytes();
    }

    /** A release came due and its cycle starts now (cycle's thread). */
    void released(long latenessNs) {
        increment(releases);
        increment(runs);
        this.latenessNs = record(this.latenessNs, latenessNs);
        latenessSumNs += latenessNs;
        if (latenessNs > latenessMaxNs) {
            latenessMaxNs = latenessNs;
        }
    }

    /** A cycle ended after {@code execNs} of world time (cycle's thread). */
    void cycleEnded(long execNs) {
        this.execNs = record(this.execNs, execNs);
        execSumNs += execNs;
        if (execNs > execMaxNs) {
            execMaxNs = execNs;
        }
        long n = recentExecCount.getPlain();
        recentExecNs.setRelease((int) (n % RECENT_EXEC_CYCLES), execNs);
        recentExecCount.setRelease(n + 1);
    }

    /** {@code count} releases were skipped, each a release and a miss (cycle's thread). */
    void skipped(long count) {
        releases.setRelease(releases.getPlain() + count);
        skipped.setRelease(skipped.getPlain() + count);
        misses.addAndGet(count);
    }

    /** A cycle missed its deadline (cycle's thread or watchdog). */
    void missed() {
        misses.incrementAndGet();
    }

    void staleRun() {
        increment(staleRuns);
    }

    void error() {
        increment(errors);
    }

    void expiredRead() {
        increment(expiredReads);
    }

    /** A listener failed on one of this task's events (any thread). */
    void listenerError() {
        listenerErrors.incrementAndGet();
    }

    long releases() {
        return releases.get();
    }

    long runs() {
        return runs.get();
    }

    long misses() {
        return misses.get();
    }

    long skippedReleases() {
        return skipped.get();
    }

    long staleRuns() {
        return staleRuns.get();
    }

    long errors() {
        return errors.get();
    }

    long expiredReads() {
        return expiredReads.get();
    }

    long listenerErrors() {
        return listenerErrors.get();
    }

    /** Live counters, safe at any time from any thread; allocates (not for the cycle's thread). */
    TaskCounters counters() {
        return new TaskCounters(releases.get(), runs.get(), misses.get(), skipped.get(), staleRuns.get(),
                errors.get(), expiredReads.get(), recentExecP99Ns());
    }

    /**
     * The 99th percentile of the latest {@value #RECENT_EXEC_CYCLES} cycles' execution times (of
     * all cycles before that many have run), exact: with n values sorted, the ceil(0.99 n)-th,
     * as HdrHistogram ranks them; 0 before the first cycle. A cycle that ends during the read
     * may replace the oldest value read, which a live figure can afford.
     */
    private long recentExecP99Ns() {
        long count = recentExecCount.getAcquire();
        int n = (int) Math.min(count, RECENT_EXEC_CYCLES);
        if (n == 0) {
            return 0;
        }
        long[] latest = new long[n];
        for (int i = 0; i < n; i++) {
            latest[i] = recentExecNs.getAcquire(i);
        }
        Arrays.sort(latest);
        return latest[(int) Math.ceil(0.99 * n) - 1];
    }

    /** @return execution times over the run; call only after the task's cycles have stopped */
    Percentiles execUs() {
        return Percentiles.ofNanos(execNs, execMaxNs, execSumNs);
    }

    /** @return lateness over the run; call only after the task's cycles have stopped */
    Percentiles latenessUs() {
        return Percentiles.ofNanos(latenessNs, latenessMaxNs, latenessSumNs);
    }

    private static AbstractHistogram newHistogram() {
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

    /** Single writer: an ordered store instead of an atomic increment. */
    private static void increment(AtomicLong counter) {
        counter.setRelease(counter.getPlain() + 1);
    }
}
