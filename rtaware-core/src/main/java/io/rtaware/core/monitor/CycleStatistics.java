package io.rtaware.core.monitor;

import io.rtaware.core.report.Percentiles;
import java.util.concurrent.atomic.AtomicLong;
import org.HdrHistogram.Histogram;
import org.HdrHistogram.SingleWriterRecorder;

/**
 * One task's counts and distributions: what the report and the live counters say about it.
 *
 * <p>Writers: the task's thread records every cycle; the watchdog adds misses it detects, and
 * any thread may count a listener fault. Counts written by the task's thread alone are
 * published with ordered stores (no read-modify-write on the hot path); misses, which two
 * threads add, are atomic. Execution times go to an HdrHistogram {@link SingleWriterRecorder}:
 * readers take its interval histograms, which feed both the whole-run distribution and the live
 * p99 of the latest cycles, while the task's thread records without locks or allocation.
 * Lateness is only reported at the end, so it goes to a plain histogram read after the task's
 * thread has stopped.
 */
final class CycleStatistics {

    private static final long HIGHEST_TRACKABLE_NS = 3_600_000_000_000L;
    private static final int SIGNIFICANT_DIGITS = 2;
    /** The live p99 covers at least this many of the latest cycles, once that many have run. */
    static final int RECENT_EXEC_CYCLES = 128;

    /**
     * Histograms one instance holds: lateness, the recorder's two, the whole run's, the interval,
     * and the three windows of the live p99.
     */
    private static final int HISTOGRAMS = 8;

    private final AtomicLong releases = new AtomicLong();
    private final AtomicLong runs = new AtomicLong();
    private final AtomicLong misses = new AtomicLong();
    private final AtomicLong skipped = new AtomicLong();
    private final AtomicLong staleRuns = new AtomicLong();
    private final AtomicLong errors = new AtomicLong();
    private final AtomicLong expiredReads = new AtomicLong();
    private final AtomicLong listenerErrors = new AtomicLong();

    private final Histogram latenessNs = new Histogram(1, HIGHEST_TRACKABLE_NS, SIGNIFICANT_DIGITS);
    private long latenessMaxNs;
    private double latenessSumNs;

    private final SingleWriterRecorder execRecorder =
            new SingleWriterRecorder(1, HIGHEST_TRACKABLE_NS, SIGNIFICANT_DIGITS);
    private long execMaxNs;
    private double execSumNs;

    // Reader side of the execution-time recorder, guarded by this object's monitor. Created on
    // the first read that needs them (the whole run at the report, the recent windows at the
    // first live p99), by the reader: a histogram of this range is ~35 KB, and a monitor of
    // 1000 tasks that nobody reads live would otherwise zero 140 MB of them at build time
    // (issue 16's profile: Histogram.<init> under Monitor.Builder.build was 60 % of the
    // allocation and a quarter of the main thread's samples of a 1000-task comparison).
    private Histogram execWholeRunNs;
    private Histogram execIntervalNs;
    /** The latest cycles since the first live read: the previous full window and the one filling up. */
    private Histogram execOlderNs;
    private Histogram execNewerNs;
    private Histogram execRecentNs;

    /**
     * @return the heap bytes one instance's histograms take, as HdrHistogram estimates them
     */
    static long estimatedHeapBytes() {
        return HISTOGRAMS * new Histogram(1, HIGHEST_TRACKABLE_NS, SIGNIFICANT_DIGITS).getEstimatedFootprintInBytes();
    }

    /** A release came due and its cycle starts now (task thread). */
    void released(long latenessNs) {
        increment(releases);
        increment(runs);
        this.latenessNs.recordValue(clamp(latenessNs));
        latenessSumNs += latenessNs;
        if (latenessNs > latenessMaxNs) {
            latenessMaxNs = latenessNs;
        }
    }

    /** A cycle ended after {@code execNs} of world time (task thread). */
    void cycleEnded(long execNs) {
        execRecorder.recordValue(clamp(execNs));
        execSumNs += execNs;
        if (execNs > execMaxNs) {
            execMaxNs = execNs;
        }
    }

    /** {@code count} releases were skipped, each a release and a miss (task thread). */
    void skipped(long count) {
        releases.setRelease(releases.getPlain() + count);
        skipped.setRelease(skipped.getPlain() + count);
        misses.addAndGet(count);
    }

    /** A cycle missed its deadline (task thread or watchdog). */
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

    /** Live counters, safe at any time from any thread; allocates (not for task threads). */
    TaskCounters counters() {
        return new TaskCounters(releases.get(), runs.get(), misses.get(), skipped.get(), staleRuns.get(),
                errors.get(), expiredReads.get(), recentExecP99Ns());
    }

    /**
     * The 99th percentile (to HdrHistogram's two significant digits) of the latest cycles'
     * execution times: the window filling up plus the previous full one, so at least the latest
     * {@value #RECENT_EXEC_CYCLES} cycles once that many have run; 0 before the first cycle.
     */
    private synchronized long recentExecP99Ns() {
        if (execRecentNs == null) {
            execOlderNs = newHistogram();
            execNewerNs = newHistogram();
            execRecentNs = newHistogram();
        }
        drainExecRecorder();
        execRecentNs.reset();
        execRecentNs.add(execOlderNs);
        execRecentNs.add(execNewerNs);
        return execRecentNs.getTotalCount() == 0 ? 0 : execRecentNs.getValueAtPercentile(99);
    }

    /** Moves what the task recorded since the last read into the whole-run and recent windows. */
    private void drainExecRecorder() {
        if (execWholeRunNs == null) {
            execWholeRunNs = newHistogram();
        }
        execIntervalNs = execRecorder.getIntervalHistogram(execIntervalNs);
        if (execIntervalNs.getTotalCount() == 0) {
            return;
        }
        execWholeRunNs.add(execIntervalNs);
        if (execNewerNs == null) {
            return; // nobody reads the live p99: no recent windows to keep
        }
        execNewerNs.add(execIntervalNs);
        if (execNewerNs.getTotalCount() >= RECENT_EXEC_CYCLES) {
            Histogram full = execNewerNs;
            execNewerNs = execOlderNs;
            execNewerNs.reset();
            execOlderNs = full;
        }
    }

    private static Histogram newHistogram() {
        return new Histogram(1, HIGHEST_TRACKABLE_NS, SIGNIFICANT_DIGITS);
    }

    /** @return execution times over the run; call only after the task's thread has stopped */
    synchronized Percentiles execUs() {
        drainExecRecorder();
        return Percentiles.ofNanos(execWholeRunNs, execMaxNs, execSumNs);
    }

    /** @return lateness over the run; call only after the task's thread has stopped */
    Percentiles latenessUs() {
        return Percentiles.ofNanos(latenessNs, latenessMaxNs, latenessSumNs);
    }

    /** Single writer: an ordered store instead of an atomic increment. */
    private static void increment(AtomicLong counter) {
        counter.setRelease(counter.getPlain() + 1);
    }

    private static long clamp(long valueNs) {
        return Math.min(Math.max(valueNs, 1), HIGHEST_TRACKABLE_NS);
    }
}
