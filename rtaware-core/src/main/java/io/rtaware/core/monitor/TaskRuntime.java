package io.rtaware.core.monitor;

import io.rtaware.core.report.Percentiles;
import io.rtaware.core.report.Rounding;
import io.rtaware.core.report.TaskReport;
import io.rtaware.core.task.ErrorPolicy;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.Clock;
import java.util.Arrays;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicLongArray;
import org.HdrHistogram.Histogram;

/**
 * One task under the monitor: its inputs and outputs, the timing rules, and its statistics.
 * Both executors drive a task through this class only, so the rules are the same on real
 * threads and in the step executor:
 * <ul>
 *   <li>release k of a periodic task is at {@code base + k * period}, with
 *   {@code base = start + offset};</li>
 *   <li>a cycle that has not returned by {@code release + deadline} is a miss, reported by the
 *   watchdog at that moment ({@link #checkDeadline(long)}) or, failing that, when it returns;</li>
 *   <li>a cycle that returns after later releases came due skips to the first grid point at or
 *   after its end; every skipped release counts as a release and a miss, and is never run
 *   (no catch-up bursts);</li>
 *   <li>a cycle whose inputs had no new data is a stale run (tasks without inputs never are);</li>
 *   <li>with an {@link AdaptivePolicy} and a period range, the period moves at the end of an
 *   evaluation window ({@link #nextIndexAfter}); the grid is then re-anchored at the next
 *   release n on the old grid: release {@code n + j} is at {@code t_n + j * newPeriod}.</li>
 * </ul>
 *
 * <p>Thread-safety: {@link #runCycle} and {@link #nextIndexAfter} are called by the task's own
 * thread only; {@link #checkDeadline(long)} by the watchdog, concurrently, coordinated with the
 * task thread through one atomic cycle token. Counters are safe to read at any time; the
 * histograms and the period history only after the task thread has stopped. The grid is one
 * immutable object in a volatile field, replaced only between cycles by the task's thread, so
 * the watchdog always sees a consistent grid.
 */
final class TaskRuntime implements TaskInfo {

    /** Result of one cycle, telling the executor what to do next. */
    enum Outcome { CONTINUE, DISABLE, STOP_ALL }

    private static final long HIGHEST_TRACKABLE_NS = 3_600_000_000_000L;
    /** Cycles whose execution times {@link #counters()} summarizes as a live p99. */
    static final int RECENT_EXEC_CYCLES = 128;
    /** Bookkeeping besides the histograms and the recent ring: runtime, counters, spec, thread object. */
    private static final long FIXED_OVERHEAD_BYTES = 16 * 1024;

    /**
     * Heap bytes one task's bookkeeping takes: its two histograms (as HdrHistogram estimates
     * their footprint), the recent-execution ring and a fixed allowance for the rest. Not the
     * task's own data, nor its thread's stack (native memory).
     *
     * @return the estimate in bytes
     */
    static long estimatedHeapBytes() {
        long histogram = new Histogram(1, HIGHEST_TRACKABLE_NS, 2).getEstimatedFootprintInBytes();
        return 2 * histogram + 2L * RECENT_EXEC_CYCLES * Long.BYTES + FIXED_OVERHEAD_BYTES;
    }

    private final TaskSpec spec;
    private final int index;
    private final Clock clock;
    private MonitorListener[] listeners;
    private final InputHandle<?>[] inputs;
    private final OutputHandle<?>[] outputs;
    private final boolean periodic;
    private final long offsetNs;
    private long startNs;

    /**
     * The release grid: release k is at {@code baseNs + (k - baseIndex) * periodNs}.
     *
     * @param baseIndex the release index at {@code baseNs}
     * @param baseNs the grid's anchor in world time
     * @param periodNs the period
     * @param deadlineNs the relative deadline
     */
    private record Grid(long baseIndex, long baseNs, long periodNs, long deadlineNs) {
        long releaseNs(long k) {
            return baseNs + (k - baseIndex) * periodNs;
        }
    }

    private volatile Grid grid;

    /** Adaptive periods: null unless enabled on the monitor and the schedule has a range. */
    private AdaptivePolicy adaptive;
    private final java.util.List<PeriodChange> periodHistory = new java.util.ArrayList<>();
    private long windowReleases;
    private long windowMisses;
    private long windowRuns;
    private long windowStale;
    private long windowExecMaxNs;

    /** Odd {@code 2k+1}: cycle k is running. Even: no cycle running (claims move it to 2k+2). */
    private final AtomicLong cycleToken = new AtomicLong(0);

    private final AtomicLong releases = new AtomicLong();
    private final AtomicLong runs = new AtomicLong();
    private final AtomicLong misses = new AtomicLong();
    private final AtomicLong skipped = new AtomicLong();
    private final AtomicLong staleRuns = new AtomicLong();
    private final AtomicLong errors = new AtomicLong();
    private final AtomicLong expiredReads = new AtomicLong();
    private volatile TaskState state = TaskState.INITIALIZED;
    /** Called on the task thread once a periodic cycle is marked running; null if none. */
    private Runnable cycleStarted;

    private final Histogram execNs = new Histogram(1, HIGHEST_TRACKABLE_NS, 2);
    private final Histogram latenessNs = new Histogram(1, HIGHEST_TRACKABLE_NS, 2);
    private long execMaxNs;
    private double execSumNs;
    /** Execution times of the latest cycles, a ring written by the task thread, read by anyone. */
    private final AtomicLongArray recentExecNs = new AtomicLongArray(RECENT_EXEC_CYCLES);
    /** Next slot of {@link #recentExecNs}; task thread only. */
    private int recentExecSlot;
    private long latenessMaxNs;
    /** End of the latest cycle; task thread only. */
    private long lastCycleEndNs;
    /** Whether the latest cycle threw; task thread only. */
    private boolean lastCycleFailed;
    private double latenessSumNs;

    TaskRuntime(TaskSpec spec, int index, Clock clock, MonitorListener[] listeners,
                InputHandle<?>[] inputs, OutputHandle<?>[] outputs) {
        this.spec = spec;
        this.index = index;
        this.clock = clock;
        this.listeners = listeners;
        this.inputs = inputs;
        this.outputs = outputs;
        Schedule schedule = spec.schedule();
        if (schedule instanceof Schedule.Periodic p) {
            periodic = true;
            offsetNs = p.offsetNs();
            grid = new Grid(0, 0, p.periodNs(), p.deadlineNs());
        } else {
            periodic = false;
            offsetNs = schedule instanceof Schedule.Once o ? o.offsetNs() : 0;
            grid = new Grid(0, 0, 0, 0);
        }
    }

    @Override
    public String name() {
        return spec.name();
    }

    @Override
    public int index() {
        return index;
    }

    @Override
    public Schedule schedule() {
        return spec.schedule();
    }

    /** Replaces the listeners; only before the task's thread starts (the start publishes it). */
    void listeners(MonitorListener[] all) {
        this.listeners = all;
    }

    TaskSpec spec() {
        return spec;
    }

    OutputHandle<?>[] outputs() {
        return outputs;
    }

    InputHandle<?>[] inputs() {
        return inputs;
    }

    boolean isPeriodic() {
        return periodic;
    }

    /**
     * Enables adaptive periods for this task if its schedule declares a range; only before the
     * task's thread starts.
     */
    void adaptive(AdaptivePolicy policy) {
        if (spec.schedule() instanceof Schedule.Periodic p && p.isAdaptive()) {
            this.adaptive = policy;
        }
    }

    /**
     * Sets the hook run on the task thread right after a periodic cycle is marked running (the
     * threaded executor wakes its watchdog there). Call before the task's thread starts.
     *
     * @param hook must not allocate or block
     */
    void onCycleStart(Runnable hook) {
        this.cycleStarted = hook;
    }

    /** Fixes the grid: release k of a periodic task is at {@code startNs + offset + k * period}. */
    void begin(long startNs) {
        this.startNs = startNs;
        Grid g = grid;
        grid = new Grid(0, startNs + offsetNs, g.periodNs(), g.deadlineNs());
        setState(TaskState.RUNNING, startNs);
    }

    /** @return the world time of release k (periodic), or of the single run (once/continuous) */
    long releaseTimeNs(long k) {
        Grid g = grid;
        return periodic ? g.releaseNs(k) : g.baseNs();
    }

    /** @return the absolute deadline of release k, or {@link Long#MAX_VALUE} if not periodic */
    long deadlineOf(long k) {
        Grid g = grid;
        return periodic ? g.releaseNs(k) + g.deadlineNs() : Long.MAX_VALUE;
    }

    /** @return the current period in world nanoseconds (0 unless periodic) */
    long periodNs() {
        return grid.periodNs();
    }

    /** @return every period change so far; call only after the task thread has stopped */
    java.util.List<PeriodChange> periodHistory() {
        return java.util.List.copyOf(periodHistory);
    }

    /** Index of the release the task's thread waits for next; -1 before the first. */
    private volatile long pendingIndex = -1;

    /**
     * Publishes the release the task's thread is about to wait for, so the watchdog can sleep
     * until the earliest deadline that could be missed instead of being woken at every cycle start.
     *
     * @param k the next release index
     */
    void pending(long k) {
        pendingIndex = k;
    }

    /**
     * @return the deadline of the running cycle, or else of the release the task waits for; or
     *     {@link Long#MAX_VALUE} if not periodic or not yet waiting
     */
    long pendingDeadlineNs() {
        long running = runningDeadlineNs();
        if (running != Long.MAX_VALUE) {
            return running;
        }
        long k = pendingIndex;
        return k < 0 ? Long.MAX_VALUE : deadlineOf(k);
    }

    /**
     * @return the absolute deadline of the cycle running now, or {@link Long#MAX_VALUE} if none
     */
    long runningDeadlineNs() {
        long token = cycleToken.get();
        return (token & 1) == 1 ? deadlineOf((token - 1) >>> 1) : Long.MAX_VALUE;
    }

    /**
     * Runs one cycle for release {@code k}: copy-in, execute, commit, bookkeeping.
     *
     * @param k the release index (for continuous tasks a running count)
     * @param releaseNs the scheduled release time
     * @return what the executor must do next
     */
    Outcome runCycle(long k, long releaseNs) {
        long startNs = clock.nanos();
        releases.incrementAndGet();
        runs.incrementAndGet();
        long lateness = Math.max(0, startNs - releaseNs);
        record(latenessNs, lateness);
        latenessSumNs += lateness;
        if (lateness > latenessMaxNs) {
            latenessMaxNs = lateness;
        }
        if (periodic) {
            cycleToken.set(2 * k + 1);
            if (cycleStarted != null) {
                cycleStarted.run();
            }
        }

        boolean anyNew = false;
        for (InputHandle<?> input : inputs) {
            anyNew |= input.refresh(startNs);
            if (input.isExpired()) {
                expiredReads.incrementAndGet();
                for (MonitorListener l : listeners) {
                    l.onExpiredInput(this, input.key().name(), input.ageNs(), input.maxAgeNs(), startNs);
                }
            }
        }
        if (inputs.length > 0 && !anyNew) {
            staleRuns.incrementAndGet();
            for (MonitorListener l : listeners) {
                l.onStaleRun(this, startNs);
            }
        }

        Throwable failure = null;
        try {
            spec.task().execute(startNs);
        } catch (VirtualMachineError fatal) {
            throw fatal;
        } catch (Throwable t) {
            failure = t;
        }

        long endNs;
        if (failure == null) {
            endNs = clock.nanos();
            for (OutputHandle<?> output : outputs) {
                long generation = output.commitIfMarked(endNs);
                if (generation != 0) {
                    for (MonitorListener l : listeners) {
                        l.onCommit(this, output.keyIndex(), generation, endNs);
                    }
                }
            }
        } else {
            for (OutputHandle<?> output : outputs) {
                output.discard();
            }
            endNs = clock.nanos();
        }

        if (periodic && cycleToken.compareAndSet(2 * k + 1, 2 * k + 2)) {
            // The watchdog had not claimed this cycle: a late finish is reported now.
            long deadline = deadlineOf(k);
            if (endNs > deadline) {
                misses.incrementAndGet();
                for (MonitorListener l : listeners) {
                    l.onDeadlineMiss(this, releaseNs, deadline, endNs, false);
                }
            }
        }
        lastCycleEndNs = endNs;
        long exec = endNs - startNs;
        if (exec > windowExecMaxNs) {
            windowExecMaxNs = exec;
        }
        record(execNs, exec);
        recentExecNs.setRelease(recentExecSlot, Math.max(exec, 1));
        recentExecSlot = (recentExecSlot + 1) % RECENT_EXEC_CYCLES;
        execSumNs += exec;
        if (exec > execMaxNs) {
            execMaxNs = exec;
        }
        for (MonitorListener l : listeners) {
            l.onCycle(this, releaseNs, startNs, endNs);
        }
        lastCycleFailed = failure != null;
        if (failure != null) {
            return fail(failure, endNs);
        }
        return Outcome.CONTINUE;
    }

    private Outcome fail(Throwable failure, long nowNs) {
        errors.incrementAndGet();
        ErrorPolicy policy = spec.errorPolicy();
        for (MonitorListener l : listeners) {
            l.onTaskError(this, failure, policy, nowNs);
        }
        return switch (policy) {
            case CONTINUE -> Outcome.CONTINUE;
            case DISABLE_TASK -> Outcome.DISABLE;
            case STOP_ALL -> Outcome.STOP_ALL;
        };
    }

    /**
     * The watchdog's check: if the running cycle is past its deadline, claims it and reports the
     * miss now, while the task is still running.
     *
     * @param nowNs world time
     */
    void checkDeadline(long nowNs) {
        long token = cycleToken.get();
        if ((token & 1) == 0) {
            return;
        }
        long k = (token - 1) >>> 1;
        long deadline = deadlineOf(k);
        if (nowNs <= deadline || !cycleToken.compareAndSet(token, token + 1)) {
            return;
        }
        misses.incrementAndGet();
        for (MonitorListener l : listeners) {
            l.onDeadlineMiss(this, releaseTimeNs(k), deadline, nowNs, true);
        }
    }

    /**
     * The release to run after release {@code k} whose cycle ended at {@code endNs}: the next grid
     * point, or, if the cycle overran, the first grid point at or after its end. Each grid point
     * passed over is counted as a release, a skipped release and a miss. With adaptive periods,
     * this is also where an evaluation window ends and the grid may be re-anchored.
     *
     * @param k the release just run
     * @param endNs when its cycle ended
     * @return the index of the next release to run
     */
    long nextIndexAfter(long k, long endNs) {
        Grid g = grid;
        long periodNs = g.periodNs();
        long next = k + 1;
        long since = endNs - g.baseNs();
        if (since > (next - g.baseIndex()) * periodNs) {
            // ceil: first grid point >= end
            long first = g.baseIndex() + Math.floorDiv(since + periodNs - 1, periodNs);
            long passed = first - next;
            releases.addAndGet(passed);
            skipped.addAndGet(passed);
            misses.addAndGet(passed);
            for (MonitorListener l : listeners) {
                l.onSkippedReleases(this, passed, endNs);
            }
            next = first;
        }
        if (adaptive != null) {
            adapt(next, endNs);
        }
        return next;
    }

    /**
     * Ends an evaluation window when it is full and applies the {@link AdaptivePolicy}; a change
     * re-anchors the grid at release {@code next}, which stays where the old grid put it.
     */
    private void adapt(long next, long endNs) {
        long rel = releases.get() - windowReleases;
        if (rel < adaptive.windowReleases()) {
            return;
        }
        long miss = misses.get() - windowMisses;
        long ran = runs.get() - windowRuns;
        long stale = staleRuns.get() - windowStale;
        long execMax = windowExecMaxNs;
        windowReleases += rel;
        windowMisses += miss;
        windowRuns += ran;
        windowStale += stale;
        windowExecMaxNs = 0;

        Schedule.Periodic declared = (Schedule.Periodic) spec.schedule();
        Grid g = grid;
        long period = g.periodNs();
        long longer = Math.min(declared.maxPeriodNs(), roundToMicros(period * adaptive.stepFactor()));
        long shorter = Math.max(declared.minPeriodNs(), roundToMicros(period / adaptive.stepFactor()));
        long target = period;
        PeriodChange.Reason reason = null;
        if (miss > 0) {
            target = longer;
            reason = PeriodChange.Reason.MISSES;
        } else if (inputs.length > 0 && stale * 100.0 >= adaptive.staleLongerPct() * ran) {
            target = longer;
            reason = PeriodChange.Reason.STALE;
        } else if ((inputs.length == 0 || stale * 100.0 <= adaptive.staleShorterPct() * ran)
                && execMax * 100.0 <= adaptive.headroomPct() * shorter) {
            target = shorter;
            reason = PeriodChange.Reason.FRESH_WITH_HEADROOM;
        }
        if (target == period) {
            return;
        }
        long anchorNs = g.releaseNs(next);
        long deadline = declared.withPeriod(target).deadlineNs();
        grid = new Grid(next, anchorNs, target, deadline);
        PeriodChange change = new PeriodChange(name(), anchorNs - startNs, period, target, reason, rel, miss, ran,
                stale, execMax);
        periodHistory.add(change);
        for (MonitorListener l : listeners) {
            l.onPeriodChange(this, change, endNs);
        }
    }

    private static long roundToMicros(double ns) {
        return Math.max(1_000, Math.round(ns / 1_000) * 1_000);
    }

    /** @return true if the latest cycle threw (task thread only) */
    boolean lastCycleFailed() {
        return lastCycleFailed;
    }

    /** @return world time at which the latest cycle ended (task thread only) */
    long lastCycleEndNs() {
        return lastCycleEndNs;
    }

    void setState(TaskState newState, long nowNs) {
        state = newState;
        for (MonitorListener l : listeners) {
            l.onStateChange(this, newState, nowNs);
        }
    }

    TaskState state() {
        return state;
    }

    long misses() {
        return misses.get();
    }

    long releases() {
        return releases.get();
    }

    private static void record(Histogram histogram, long valueNs) {
        histogram.recordValue(Math.min(Math.max(valueNs, 1), HIGHEST_TRACKABLE_NS));
    }

    /** Live counters, safe at any time from any thread; allocates (not for task threads). */
    TaskCounters counters() {
        return new TaskCounters(releases.get(), runs.get(), misses.get(), skipped.get(), staleRuns.get(),
                errors.get(), expiredReads.get(), recentExecP99Ns());
    }

    /** p99 (nearest rank) of the execution times in the ring, 0 before the first cycle. */
    private long recentExecP99Ns() {
        long[] values = new long[RECENT_EXEC_CYCLES];
        int n = 0;
        for (int i = 0; i < RECENT_EXEC_CYCLES; i++) {
            long v = recentExecNs.getAcquire(i);
            if (v > 0) {
                values[n++] = v;
            }
        }
        if (n == 0) {
            return 0;
        }
        Arrays.sort(values, 0, n);
        return values[(int) Math.ceil(0.99 * n) - 1];
    }

    /** Builds the report; call only after the task thread has stopped. */
    TaskReport report() {
        long rel = releases.get();
        long miss = misses.get();
        Grid g = grid;
        Double period = periodic ? g.periodNs() / 1e6 : null;
        Double deadline = periodic ? g.deadlineNs() / 1e6 : null;
        return new TaskReport(name(), spec.schedule().kind(), period, deadline, rel, runs.get(), miss,
                rel == 0 ? 0.0 : round2(100.0 * miss / rel), skipped.get(), staleRuns.get(), errors.get(),
                expiredReads.get(), Percentiles.ofNanos(execNs, execMaxNs, execSumNs),
                Percentiles.ofNanos(latenessNs, latenessMaxNs, latenessSumNs));
    }

    static double round2(double v) {
        return Rounding.toDecimals(v, 2);
    }
}
