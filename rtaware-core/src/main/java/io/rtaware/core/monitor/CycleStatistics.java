package io.rtaware.core.monitor;

import io.rtaware.core.report.Percentiles;
import java.lang.invoke.MethodHandles;
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
 * path); misses, which two threads add, are atomic. The counters are plain fields of this one
 * object, accessed through {@link VarHandle}s, rather than an object each: with thousands of
 * tasks a pool worker finds every task's state out of its caches, and each object touched per
 * cycle is one more cache miss (issue 16's profile at 10 000 tasks).
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
     * Lateness and execution times wait in small rings and go into their histograms this many at
     * a time: with thousands of tasks a histogram is out of the caches at every cycle, and one
     * touch per batch instead of one per cycle is the saving (issue 16's profiles at 10 000
     * tasks: recording into the two histograms took a third to a half of the workers' samples,
     * most of them the first read of the histogram's minimum and maximum). Execution times wait
     * in the ring of recent ones (written anyway for the live p99), lateness in a ring of its own
     * of this size. Divides {@link #RECENT_EXEC_CYCLES}, so a waiting value is never overwritten.
     * Each task flushes at its own phase of the batch ({@link #CycleStatistics(int)}): tasks
     * released together would otherwise all record a whole batch in the same cycle, and with
     * 10 000 tasks in phase every 16th period took 7.5 ms to release instead of 2.7 ms (issue
     * 16: the longest release of each period, period by period, showed the spikes 16 periods
     * apart, and they set every task's p99).
     */
    static final int RECORD_BATCH = 16;
    /**
     * Heap besides HdrHistogram's footprint estimate of the histograms and the rings' elements:
     * this object, the rings' headers, and what the histograms' objects take beyond that estimate
     * (80 bytes each), as {@code MonitorFootprintTest} measures them with the JVM's allocation
     * counter.
     */
    private static final long FIELDS_BYTES = 416;

    // Atomic adds are invoked on these constants directly and with getAndAdd's exact type
    // ((long) H.getAndAdd(this, long)): a VarHandle passed as an argument is not a constant, and
    // where such a call is not compiled yet (a path first taken in steady state, e.g. the first
    // miss), its access check allocated strings (seen by the Epsilon guard, JFR stack
    // VarHandle.checkExactAccessMode <- missed()).
    private static final VarHandle RELEASES;
    private static final VarHandle RUNS;
    private static final VarHandle MISSES;
    private static final VarHandle SKIPPED;
    private static final VarHandle STALE_RUNS;
    private static final VarHandle ERRORS;
    private static final VarHandle EXPIRED_READS;
    private static final VarHandle LISTENER_ERRORS;
    private static final VarHandle RECENT_EXEC_COUNT;
    private static final VarHandle RECENT_EXEC_SLOT = MethodHandles.arrayElementVarHandle(long[].class);

    static {
        try {
            MethodHandles.Lookup lookup = MethodHandles.lookup();
            RELEASES = lookup.findVarHandle(CycleStatistics.class, "releases", long.class);
            RUNS = lookup.findVarHandle(CycleStatistics.class, "runs", long.class);
            MISSES = lookup.findVarHandle(CycleStatistics.class, "misses", long.class);
            SKIPPED = lookup.findVarHandle(CycleStatistics.class, "skipped", long.class);
            STALE_RUNS = lookup.findVarHandle(CycleStatistics.class, "staleRuns", long.class);
            ERRORS = lookup.findVarHandle(CycleStatistics.class, "errors", long.class);
            EXPIRED_READS = lookup.findVarHandle(CycleStatistics.class, "expiredReads", long.class);
            LISTENER_ERRORS = lookup.findVarHandle(CycleStatistics.class, "listenerErrors", long.class);
            RECENT_EXEC_COUNT = lookup.findVarHandle(CycleStatistics.class, "recentExecCount", long.class);
        } catch (ReflectiveOperationException e) {
            throw new ExceptionInInitializerError(e);
        }
    }

    // Written through the VarHandles above: ordered stores by the cycle's thread, atomic adds
    // where two threads write (misses, listener errors), acquiring reads by anyone.
    private long releases;
    private long runs;
    private long misses;
    private long skipped;
    private long staleRuns;
    private long errors;
    private long expiredReads;
    private long listenerErrors;

    private AbstractHistogram latenessNs = newHistogram();
    private long latenessMaxNs;
    private double latenessSumNs;
    /** Lateness values not yet in {@link #latenessNs}: slot {@code n % RECORD_BATCH} for the n-th release. */
    private final long[] pendingLatenessNs = new long[RECORD_BATCH];
    /** Lateness values noted so far. */
    private long latenessCount;
    /** Lateness values recorded into {@link #latenessNs} so far (the rest wait in the ring). */
    private long latenessRecordedCount;

    private AbstractHistogram execNs = newHistogram();
    private long execMaxNs;
    private double execSumNs;

    /** The latest execution times, slot {@code n % RECENT_EXEC_CYCLES} for the n-th cycle. */
    private final long[] recentExecNs = new long[RECENT_EXEC_CYCLES];
    /** Execution times written to {@link #recentExecNs} so far. */
    private long recentExecCount;
    /** Execution times recorded into {@link #execNs} so far (the rest wait in the ring). */
    private long execRecordedCount;
    /** The values wait until the count of values noted is {@code flushPhase} modulo {@link #RECORD_BATCH}. */
    private final int flushPhase;

    /** Statistics that flush their batches when the count of values noted is a multiple of {@link #RECORD_BATCH}. */
    CycleStatistics() {
        this(0);
    }

    /**
     * @param spreadIndex spreads the batches of many tasks over the cycles: a task's waiting
     *     values go into its histograms when the count noted is {@code spreadIndex} modulo
     *     {@link #RECORD_BATCH} (the task's index serves; the first batch is then shorter)
     */
    CycleStatistics(int spreadIndex) {
        this.flushPhase = Math.floorMod(spreadIndex, RECORD_BATCH);
    }

    /**
     * @return the heap bytes one instance takes: its two histograms as HdrHistogram estimates
     *     their footprint, the rings of recent execution times and of lateness values waiting to
     *     be recorded, and its fields
     */
    static long estimatedHeapBytes() {
        return 2 * newHistogram().getEstimatedFootprintInBytes()
                + (long) (RECENT_EXEC_CYCLES + RECORD_BATCH) * Long.BYTES + FIELDS_BYTES;
    }

    /** @return HdrHistogram's footprint estimate of the two histograms this instance holds now */
    long histogramFootprintBytes() {
        return latenessNs.getEstimatedFootprintInBytes() + execNs.getEstimatedFootprintInBytes();
    }

    /** A release came due and its cycle starts now (cycle's thread). */
    void released(long latenessNs) {
        RELEASES.setRelease(this, releases + 1);
        RUNS.setRelease(this, runs + 1);
        latenessSumNs += latenessNs;
        if (latenessNs > latenessMaxNs) {
            latenessMaxNs = latenessNs;
        }
        long n = latenessCount;
        pendingLatenessNs[(int) (n % RECORD_BATCH)] = latenessNs;
        latenessCount = n + 1;
        if (flushDue(n + 1)) {
            recordLatenessUpTo(n + 1);
        }
    }

    /** @return whether the values waiting go into their histogram once {@code count} have been noted */
    private boolean flushDue(long count) {
        return count % RECORD_BATCH == flushPhase;
    }

    /** @return lateness values noted but not yet in their histogram (cycle's thread) */
    long latenessWaiting() {
        return latenessCount - latenessRecordedCount;
    }

    /** @return execution times noted but not yet in their histogram (cycle's thread) */
    long execWaiting() {
        return recentExecCount - execRecordedCount;
    }

    /** Records the lateness values waiting in their ring, up to the {@code count}-th (cycle's thread, or after it). */
    private void recordLatenessUpTo(long count) {
        latenessNs = recordFromRing(latenessNs, pendingLatenessNs, latenessRecordedCount, count);
        latenessRecordedCount = count;
    }

    /** A cycle ended after {@code execNs} of world time (cycle's thread). */
    void cycleEnded(long execNs) {
        execSumNs += execNs;
        if (execNs > execMaxNs) {
            execMaxNs = execNs;
        }
        long n = recentExecCount;
        RECENT_EXEC_SLOT.setRelease(recentExecNs, (int) (n % RECENT_EXEC_CYCLES), execNs);
        RECENT_EXEC_COUNT.setRelease(this, n + 1);
        if (flushDue(n + 1)) {
            recordExecUpTo(n + 1);
        }
    }

    /** Records the execution times waiting in the ring, up to the {@code count}-th (cycle's thread, or after it). */
    private void recordExecUpTo(long count) {
        execNs = recordFromRing(execNs, recentExecNs, execRecordedCount, count);
        execRecordedCount = count;
    }

    /**
     * Records the {@code from}-th to the {@code to - 1}-th value noted in a ring (the n-th in slot
     * {@code n % ring.length}).
     *
     * @return the histogram to keep (see {@link #record})
     */
    private static AbstractHistogram recordFromRing(AbstractHistogram histogram, long[] ring, long from, long to) {
        AbstractHistogram target = histogram;
        for (long i = from; i < to; i++) {
            target = record(target, ring[(int) (i % ring.length)]);
        }
        return target;
    }

    /** {@code count} releases were skipped, each a release and a miss (cycle's thread). */
    void skipped(long count) {
        RELEASES.setRelease(this, releases + count);
        SKIPPED.setRelease(this, skipped + count);
        long unused = (long) MISSES.getAndAdd(this, count);
    }

    /** A cycle missed its deadline (cycle's thread or watchdog). */
    void missed() {
        long unused = (long) MISSES.getAndAdd(this, 1L);
    }

    void staleRun() {
        STALE_RUNS.setRelease(this, staleRuns + 1);
    }

    void error() {
        ERRORS.setRelease(this, errors + 1);
    }

    void expiredRead() {
        EXPIRED_READS.setRelease(this, expiredReads + 1);
    }

    /** A listener failed on one of this task's events (any thread). */
    void listenerError() {
        long unused = (long) LISTENER_ERRORS.getAndAdd(this, 1L);
    }

    long releases() {
        return (long) RELEASES.getAcquire(this);
    }

    long runs() {
        return (long) RUNS.getAcquire(this);
    }

    long misses() {
        return (long) MISSES.getAcquire(this);
    }

    long skippedReleases() {
        return (long) SKIPPED.getAcquire(this);
    }

    long staleRuns() {
        return (long) STALE_RUNS.getAcquire(this);
    }

    long errors() {
        return (long) ERRORS.getAcquire(this);
    }

    long expiredReads() {
        return (long) EXPIRED_READS.getAcquire(this);
    }

    long listenerErrors() {
        return (long) LISTENER_ERRORS.getAcquire(this);
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
        long count = (long) RECENT_EXEC_COUNT.getAcquire(this);
        int n = (int) Math.min(count, RECENT_EXEC_CYCLES);
        if (n == 0) {
            return 0;
        }
        long[] latest = new long[n];
        for (int i = 0; i < n; i++) {
            latest[i] = (long) RECENT_EXEC_SLOT.getAcquire(recentExecNs, i);
        }
        Arrays.sort(latest);
        return latest[(int) Math.ceil(0.99 * n) - 1];
    }

    /** @return execution times over the run; call only after the task's cycles have stopped */
    Percentiles execUs() {
        recordExecUpTo(recentExecCount);
        return Percentiles.ofNanos(execNs, execMaxNs, execSumNs);
    }

    /** @return lateness over the run; call only after the task's cycles have stopped */
    Percentiles latenessUs() {
        recordLatenessUpTo(latenessCount);
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
}
