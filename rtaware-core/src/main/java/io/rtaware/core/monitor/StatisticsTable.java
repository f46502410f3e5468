package io.rtaware.core.monitor;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import org.HdrHistogram.AbstractHistogram;

/**
 * The counters and running sums of every task of one monitor, one dense array per quantity,
 * indexed by the task's index ({@link CycleStatistics} is each task's view of its column).
 *
 * <p>Why arrays and not fields of each task's object: the pool releases thousands of tasks at
 * one instant in index order, and every release updates these values. Held in one object per
 * task, they were a few cache lines per release, each out of the caches after the other tasks'
 * releases had passed; held here, consecutive tasks' values share cache lines (eight longs to a
 * 64-byte line) and a drain in index order walks each array in order. Measured (issue 36,
 * docs/performance.md): one release among 1000 in-phase tasks about a tenth cheaper on one
 * thread ({@code MonitorBench.inPhaseRelease}); the pool's drain of 10 000 not measurably
 * changed. Tasks run by different threads at once may share a line, which then moves between
 * cores: no effect was measurable with 1000 thread-per-task tasks at 100 Hz.
 *
 * <p>A cycle notes its lateness and execution time here ({@link #released}, {@link #cycleEnded});
 * the values wait, up to {@link CycleStatistics#WAITING_CAPACITY} per task, to be recorded into
 * the task's two histograms. Who records them: the cycle itself, every
 * {@link CycleStatistics#RECORD_BATCH} cycles at the task's phase ({@link #flushPhase}), or, for
 * a task {@link #recordedByRecorder recorded by a recorder}, a {@link StatisticsRecorder} thread
 * after the pool's drains; the cycle then records only if the recorder falls
 * {@link #RECORD_WHEN_WAITING} values behind, and waits for it only when the ring is full. A
 * task's histograms have one writer at a time: whoever holds the task's claim in
 * {@link #recording} ({@link #tryRecordWaiting}, {@link #recordWaiting}); the claim's
 * compare-and-set and release store order the histograms between the threads that take it.
 *
 * <p>The lateness values that wait are laid out by position in the ring first, then by task:
 * the n-th value of task i is at {@code (n % WAITING_CAPACITY) * size + i}, so tasks released
 * together write neighbouring words; the rings of recent execution times likewise
 * ({@link #ringIndex}). Tasks flush their batches in groups of {@link #TASKS_PER_LINE}
 * neighbours ({@link CycleStatistics#flushPhaseOf}), which then read the same lines one after
 * the other.
 *
 * <p>Everything else reads and writes through {@link CycleStatistics}, under the threading rules
 * stated there (one writer per task for most, ordered stores and acquiring reads for the live
 * counters). Sized once, at construction; nothing is allocated afterwards.
 *
 * <p>The table builds every task's two histograms (27 KB a task) at construction, before the
 * monitor builds its tasks' runtimes: the few small objects a release touches (the runtime and
 * its input and output handles; the grid and token are in a {@link ReleaseTable}) then lie next
 * to those of the tasks before and after it in
 * memory, rather than 27 KB apart, and a drain in index order reads memory forward, which the
 * processor's prefetcher follows (the pool's drain of 10 000 in-phase releases, measured before
 * and after: docs/performance.md, "The drain").
 */
final class StatisticsTable {

    /** Longs per 64-byte cache line: the tasks whose counters share a line. */
    static final int TASKS_PER_LINE = 8;
    /**
     * Arrays with one element per task: every one below but the waiting lateness values and the
     * rings (the histograms' references counted as longs).
     */
    static final int ARRAYS_PER_TASK = 20;
    /**
     * A cycle records its task's waiting values itself once this many wait, though a
     * {@link StatisticsRecorder} records them: the recorder has fallen behind (it runs at normal
     * priority beside workers that may be real-time, or the workers never rest), and the ring
     * must not fill. {@link CycleStatistics#WAITING_CAPACITY} minus one batch.
     */
    static final int RECORD_WHEN_WAITING = CycleStatistics.WAITING_CAPACITY - CycleStatistics.RECORD_BATCH;

    // Ordered stores and atomic adds on the arrays. Invoked on this constant directly with the
    // exact types ((long) LONGS.getAndAdd(array, int, long)): a VarHandle passed as an argument
    // is not a constant, and where such a call is not compiled yet (a path first taken in steady
    // state, e.g. the first miss), its access check allocated strings (seen by the Epsilon guard,
    // JFR stack VarHandle.checkExactAccessMode <- missed()).
    static final VarHandle LONGS = MethodHandles.arrayElementVarHandle(long[].class);
    /** Compare-and-set and release stores on {@link #recording}. */
    private static final VarHandle INTS = MethodHandles.arrayElementVarHandle(int[].class);

    /** Tasks (columns). */
    final int size;
    final long[] releases;
    final long[] runs;
    final long[] misses;
    final long[] skipped;
    final long[] staleRuns;
    final long[] errors;
    final long[] expiredReads;
    final long[] listenerErrors;
    final long[] latenessMaxNs;
    final double[] latenessSumNs;
    /** Lateness values noted so far, per task. */
    final long[] latenessCount;
    /** Lateness values recorded into the task's histogram so far (the rest wait in {@link #pendingLatenessNs}). */
    final long[] latenessRecordedCount;
    /**
     * Lateness values not yet in their histogram: the n-th of task i at {@link #ringIndex}
     * (capacity {@link CycleStatistics#WAITING_CAPACITY}).
     */
    final long[] pendingLatenessNs;
    final long[] execMaxNs;
    final double[] execSumNs;
    /** Execution times written to the task's ring of recent ones so far. */
    final long[] recentExecCount;
    /** Execution times recorded into the task's histogram so far (the rest wait in its ring). */
    final long[] execRecordedCount;
    /**
     * The latest execution times of each task, for the live p99 and waiting for the histogram:
     * the n-th of task i at {@link #ringIndex} (capacity {@link CycleStatistics#RECENT_EXEC_CYCLES}),
     * by position like the waiting lateness values,
     * so that tasks released together write neighbouring elements (one cache line per eight
     * tasks rather than one per task).
     */
    final long[] recentExecNs;
    /**
     * Per task: its cycle records its waiting values when the count of cycles ended is this
     * modulo {@link CycleStatistics#RECORD_BATCH}; when a {@link StatisticsRecorder} records
     * them, {@code -1 - phase}, which no count matches (the recorder's phase, {@link #recorderPhase}).
     */
    final int[] flushPhase;
    /** Per task: 1 while a thread records its waiting values into its histograms, else 0. */
    private final int[] recording;
    /** Each task's histogram of lateness values, ns (written on a flush; a 64-bit copy replaces it when it fills). */
    final AbstractHistogram[] latenessHistograms;
    /** Each task's histogram of execution times, ns (as {@link #latenessHistograms}). */
    final AbstractHistogram[] execHistograms;

    /**
     * @param size the number of tasks
     */
    StatisticsTable(int size) {
        if (size < 0) {
            throw new IllegalArgumentException(OffPathText.tableOfTasks(size));
        }
        this.size = size;
        releases = new long[size];
        runs = new long[size];
        misses = new long[size];
        skipped = new long[size];
        staleRuns = new long[size];
        errors = new long[size];
        expiredReads = new long[size];
        listenerErrors = new long[size];
        latenessMaxNs = new long[size];
        latenessSumNs = new double[size];
        latenessCount = new long[size];
        latenessRecordedCount = new long[size];
        pendingLatenessNs = new long[Math.multiplyExact(CycleStatistics.WAITING_CAPACITY, size)];
        execMaxNs = new long[size];
        execSumNs = new double[size];
        recentExecCount = new long[size];
        execRecordedCount = new long[size];
        recentExecNs = new long[Math.multiplyExact(CycleStatistics.RECENT_EXEC_CYCLES, size)];
        flushPhase = new int[size];
        recording = new int[size];
        latenessHistograms = new AbstractHistogram[size];
        execHistograms = new AbstractHistogram[size];
        for (int i = 0; i < size; i++) {
            latenessHistograms[i] = CycleStatistics.newHistogram();
            execHistograms[i] = CycleStatistics.newHistogram();
        }
    }

    /**
     * Notes that a release of task {@code i} came due and its cycle starts now (the task's cycle's
     * thread): counts it and keeps its lateness waiting for the histogram. If the task's ring of
     * waiting values is full (a {@link StatisticsRecorder} that has not run for
     * {@link CycleStatistics#WAITING_CAPACITY} cycles and holds the task's claim), waits for the
     * values to be recorded first: none is lost.
     *
     * @param i the task
     * @param latenessNs how late the cycle starts
     * @return whether the cycle should record the task's waiting values now
     *     ({@link #tryRecordWaiting}): its recorder has fallen behind
     */
    boolean released(int i, long latenessNs) {
        LONGS.setRelease(releases, i, releases[i] + 1);
        LONGS.setRelease(runs, i, runs[i] + 1);
        latenessSumNs[i] += latenessNs;
        if (latenessNs > latenessMaxNs[i]) {
            latenessMaxNs[i] = latenessNs;
        }
        long n = latenessCount[i];
        long waiting = n - (long) LONGS.getAcquire(latenessRecordedCount, i);
        if (waiting >= CycleStatistics.WAITING_CAPACITY) {
            recordWaiting(i);
            waiting = 0;
        }
        pendingLatenessNs[ringIndex(i, n, CycleStatistics.WAITING_CAPACITY)] = latenessNs;
        LONGS.setRelease(latenessCount, i, n + 1);
        return waiting + 1 >= RECORD_WHEN_WAITING;
    }

    /**
     * Notes that a cycle of task {@code i} ended (the task's cycle's thread): keeps its execution
     * time in the task's ring of recent ones, which is also where it waits for the histogram.
     *
     * @param i the task
     * @param execNs how long the cycle took
     * @return whether the cycle should record the task's waiting values now
     *     ({@link #tryRecordWaiting}): its phase has come, or its recorder has fallen behind
     */
    boolean cycleEnded(int i, long execNs) {
        execSumNs[i] += execNs;
        if (execNs > execMaxNs[i]) {
            execMaxNs[i] = execNs;
        }
        long n = recentExecCount[i];
        long waiting = n - (long) LONGS.getAcquire(execRecordedCount, i);
        if (waiting >= CycleStatistics.RECENT_EXEC_CYCLES) {
            recordWaiting(i);
            waiting = 0;
        }
        LONGS.setRelease(recentExecNs, ringIndex(i, n, CycleStatistics.RECENT_EXEC_CYCLES), execNs);
        LONGS.setRelease(recentExecCount, i, n + 1);
        return (n + 1) % CycleStatistics.RECORD_BATCH == flushPhase[i] || waiting + 1 >= RECORD_WHEN_WAITING;
    }

    /**
     * From now on a {@link StatisticsRecorder} records task {@code i}'s waiting values, at the
     * phase its cycle had ({@link #recorderBatchDue}): its cycle no longer does (before the
     * task's first cycle).
     */
    void recordedByRecorder(int i) {
        if (flushPhase[i] >= 0) {
            flushPhase[i] = -1 - flushPhase[i];
        }
    }

    /**
     * Whether a {@link StatisticsRecorder} should record task {@code i}'s waiting values now: a
     * batch of {@link CycleStatistics#RECORD_BATCH} values waits, or the count of lateness values
     * noted has reached the task's phase of the batch, the same phase its cycle would have
     * recorded at (so 10 000 tasks released together are recorded a sixteenth at a time, not all
     * in one pass every sixteenth period). Any thread.
     *
     * @param i a task recorded by a recorder ({@link #recordedByRecorder})
     * @return whether its values are due
     */
    boolean recorderBatchDue(int i) {
        long count = (long) LONGS.getAcquire(latenessCount, i);
        long waiting = count - (long) LONGS.getAcquire(latenessRecordedCount, i);
        long execWaiting = (long) LONGS.getAcquire(recentExecCount, i) - (long) LONGS.getAcquire(execRecordedCount, i);
        return waiting >= CycleStatistics.RECORD_BATCH || execWaiting >= CycleStatistics.RECORD_BATCH
                || ((waiting > 0 || execWaiting > 0) && count % CycleStatistics.RECORD_BATCH == recorderPhase(i));
    }

    /** @return the phase of the batch at which a recorder records task {@code i} (see {@link #recordedByRecorder}) */
    private int recorderPhase(int i) {
        return -1 - flushPhase[i];
    }

    /**
     * Records task {@code i}'s waiting values into its histograms unless another thread is
     * recording them now (any thread; nothing is allocated but a histogram's one 64-bit copy).
     *
     * @return whether this thread recorded them
     */
    boolean tryRecordWaiting(int i) {
        if (!INTS.compareAndSet(recording, i, 0, 1)) {
            return false;
        }
        try {
            recordClaimed(i);
        } finally {
            INTS.setRelease(recording, i, 0);
        }
        return true;
    }

    /**
     * Records task {@code i}'s waiting values into its histograms, first waiting for a thread
     * recording them now to finish (a report's reader, or a cycle whose ring is full).
     */
    void recordWaiting(int i) {
        while (!tryRecordWaiting(i)) {
            Thread.onSpinWait();
        }
    }

    /** Records the waiting values, holding the task's claim. */
    private void recordClaimed(int i) {
        long count = (long) LONGS.getAcquire(latenessCount, i);
        AbstractHistogram target = latenessHistograms[i];
        for (long n = latenessRecordedCount[i]; n < count; n++) {
            target = CycleStatistics.record(target, pendingLatenessNs[ringIndex(i, n, CycleStatistics.WAITING_CAPACITY)]);
        }
        latenessHistograms[i] = target;
        LONGS.setRelease(latenessRecordedCount, i, count);

        count = (long) LONGS.getAcquire(recentExecCount, i);
        target = execHistograms[i];
        for (long n = execRecordedCount[i]; n < count; n++) {
            target = CycleStatistics.record(target, recentExecNs[ringIndex(i, n, CycleStatistics.RECENT_EXEC_CYCLES)]);
        }
        execHistograms[i] = target;
        LONGS.setRelease(execRecordedCount, i, count);
    }

    /**
     * The layout of the per-task rings ({@link #pendingLatenessNs}, {@link #recentExecNs}): by
     * position in the ring first, then by task.
     *
     * @param i the task
     * @param n the number of a value of the task (from 0)
     * @param capacity the values a task's ring holds
     * @return where the value is while it is among the task's latest {@code capacity}
     */
    int ringIndex(int i, long n, int capacity) {
        return (int) (n % capacity) * size + i;
    }

    /** @return heap bytes per task: one element of each array, its waiting lateness values and its ring */
    static long bytesPerTask() {
        long longs = ARRAYS_PER_TASK + CycleStatistics.WAITING_CAPACITY + CycleStatistics.RECENT_EXEC_CYCLES;
        return longs * Long.BYTES;
    }
}
