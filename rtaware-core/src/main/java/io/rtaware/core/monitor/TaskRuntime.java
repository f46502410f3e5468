package io.rtaware.core.monitor;

import io.rtaware.core.report.Rounding;
import io.rtaware.core.report.TaskReport;
import io.rtaware.core.task.ErrorPolicy;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.Clock;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * One task under the monitor, and the rulebook of its timing: every rule of when a cycle is
 * released, skipped, late, missed, paused after an error or re-anchored after a period change
 * lives here, in world time. Executors ({@link Executor}) only wait and call: they wait until
 * {@link #nextReleaseNs()}, call {@link #runCycle()}, and repeat while the next release is not
 * {@link #NEVER}; a watchdog calls {@link #checkDeadline(long)}. The rules:
 * <ul>
 *   <li>release k of a periodic task is at {@code base + k * period}, with
 *   {@code base = start + offset} (the task's grid in the monitor's {@link ReleaseTable});</li>
 *   <li>a cycle that has not returned by {@code release + deadline} is a miss, reported by the
 *   watchdog at that moment ({@link #checkDeadline(long)}) or, failing that, when it returns
 *   (the task's deadline token in the {@link ReleaseTable} makes it exactly one of the two);</li>
 *   <li>a cycle that returns after later releases came due skips to the first grid point at or
 *   after its end; every skipped release counts as a release and a miss, and is never run
 *   (no catch-up bursts);</li>
 *   <li>a cycle whose inputs had no new data is a stale run (tasks without inputs never are);</li>
 *   <li>a cycle that throws commits nothing (its publishes are discarded) and counts as an error;
 *   its task's {@link ErrorPolicy} then decides: go on, disable the task, or stop the monitor;</li>
 *   <li>a continuous task is released again at the end of its cycle, or
 *   {@link #CONTINUOUS_ERROR_PAUSE_NS} later if the cycle threw (so a failing input cannot spin a
 *   core); a once task finishes after its single cycle;</li>
 *   <li>with an {@link AdaptivePolicy} and a period range, the period moves at the end of an
 *   evaluation window ({@link AdaptivePeriodController}); the grid is then re-anchored at the
 *   next release n on the old grid: release {@code n + j} is at {@code t_n + j * newPeriod}.</li>
 * </ul>
 *
 * <p>Where a recorder of every cycle hooks in: {@link #runCycle()} knows, in one place, the
 * release, start and end of the cycle, its lateness and execution time, whether it was stale,
 * threw or missed, and the generation each input held ({@code inputs()[i].generation()}).
 *
 * <p>Thread-safety: {@link #runCycle()} is called by one thread at a time (the task's own
 * thread, or whichever worker an executor hands the task to, with a happens-before edge between
 * consecutive callers); {@link #checkDeadline(long)} by the watchdog, concurrently, coordinated
 * through the deadline token. Counters are safe to read at any time; the distributions and
 * the period history only after the task's cycles have stopped. The grid, the next release and
 * the token are numbers in the monitor's {@link ReleaseTable}, which says how the watchdog reads
 * them while the task runs.
 */
final class TaskRuntime implements TaskInfo {

    /** {@link #nextReleaseNs()} of a task that will not be released again. */
    static final long NEVER = Long.MAX_VALUE;
    /** World time a continuous task waits after a cycle that threw, before it is released again. */
    static final long CONTINUOUS_ERROR_PAUSE_NS = 20_000_000L;

    /**
     * Bookkeeping besides the statistics: runtime, release table row, spec, the builder's declarations,
     * and the task's thread object under the threaded executor (about 1.3 KB and 0.8 KB measured
     * with the JVM's allocation counter, see {@code MonitorFootprintTest}).
     */
    private static final long FIXED_OVERHEAD_BYTES = 2560;

    /**
     * Heap bytes one task's bookkeeping takes: its cycle statistics (as HdrHistogram estimates
     * their histograms' footprint) and a measured allowance for the rest. The same with the live
     * view or adaptive periods on or off (the live p99 reads a ring every task keeps; an adaptive
     * period's controller is a few dozen bytes). Not the task's own data, nor its thread's stack
     * (native memory).
     *
     * @return the estimate in bytes
     */
    static long estimatedHeapBytes() {
        return CycleStatistics.estimatedHeapBytes() + FIXED_OVERHEAD_BYTES;
    }

    /** The input generations of every task without inputs (shared: one object less per task). */
    private static final long[] NO_GENERATIONS = new long[0];

    /** How the task is released: the only switch on the schedule's kind. */
    private enum Release { PERIODIC, CONTINUOUS, ONCE }

    private final TaskSpec spec;
    /** {@code spec.task()}, kept here: one object less for a cycle to reach (see {@link ReleaseTable}). */
    private final Task task;
    private final int index;
    private final Clock clock;
    private final ListenerFanOut events;
    private final InputHandle<?>[] inputs;
    /** Generation each input held in the latest cycle, for {@link MonitorListener#onCycleRecord}. */
    private final long[] inputGenerations;
    private final List<String> inputKeys;
    private final OutputHandle<?>[] outputs;
    private final Release release;
    private final long offsetNs;
    private final CycleStatistics statistics;
    /**
     * The table that holds {@link #statistics}' counters: a cycle notes its release and its end
     * there directly, and touches {@link #statistics} only when a batch goes into the histograms.
     */
    private final StatisticsTable statisticsTable;
    /** The table that holds this task's grid, next release and deadline token, at {@link #index}. */
    private final ReleaseTable releases;
    /** Null unless adaptive periods are enabled on the monitor and the schedule has a range. */
    private AdaptivePeriodController adaptive;
    private final List<PeriodChange> periodHistory = new ArrayList<>();
    private volatile TaskState state = TaskState.INITIALIZED;

    // Set by the executor at begin(); read by the cycle's thread.
    private long startNs;
    private Runnable stopAllRequest;
    private long zeroCycleSpacingNs;
    /** Told on the cycle's thread once a periodic cycle is marked running; null if none. */
    private Watchdog watchdog;

    TaskRuntime(TaskSpec spec, int index, StatisticsTable statisticsTable, ReleaseTable releases, Clock clock,
                ListenerFanOut events, InputHandle<?>[] inputs, OutputHandle<?>[] outputs) {
        this.spec = spec;
        this.task = spec.task();
        this.index = index;
        this.statisticsTable = statisticsTable;
        this.releases = releases;
        this.statistics = new CycleStatistics(statisticsTable, index, CycleStatistics.flushPhaseOf(index));
        this.clock = clock;
        this.events = events;
        this.inputs = inputs;
        this.inputGenerations = inputs.length == 0 ? NO_GENERATIONS : new long[inputs.length];
        List<String> names = new ArrayList<>(inputs.length);
        for (InputHandle<?> input : inputs) {
            names.add(input.key().name());
        }
        this.inputKeys = List.copyOf(names);
        this.outputs = outputs;
        Schedule schedule = spec.schedule();
        if (schedule instanceof Schedule.Periodic p) {
            release = Release.PERIODIC;
            offsetNs = p.offsetNs();
            releases.define(index, p.periodNs(), p.deadlineNs());
        } else {
            release = schedule instanceof Schedule.Once ? Release.ONCE : Release.CONTINUOUS;
            offsetNs = schedule instanceof Schedule.Once o ? o.offsetNs() : 0;
            releases.define(index, 0, 0);
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

    /** @return the table of the monitor's release bookkeeping, where this task's row is {@link #index()} */
    ReleaseTable releaseTable() {
        return releases;
    }

    /** @return the table of the monitor's statistics, where this task's column is {@link #index()} */
    StatisticsTable statisticsTable() {
        return statisticsTable;
    }

    @Override
    public Schedule schedule() {
        return spec.schedule();
    }

    TaskSpec spec() {
        return spec;
    }

    OutputHandle<?>[] outputs() {
        return outputs;
    }

    @Override
    public List<String> inputKeys() {
        return inputKeys;
    }

    InputHandle<?>[] inputs() {
        return inputs;
    }

    CycleStatistics statistics() {
        return statistics;
    }

    boolean isPeriodic() {
        return release == Release.PERIODIC;
    }

    /**
     * Enables adaptive periods for this task if its schedule declares a range; only before the
     * task's cycles start.
     */
    void adaptive(AdaptivePolicy policy) {
        if (spec.schedule() instanceof Schedule.Periodic p && p.isAdaptive()) {
            this.adaptive = new AdaptivePeriodController(policy, p, inputs.length > 0);
        }
    }

    /**
     * Sets the watchdog told of each periodic cycle right after it is marked running, with the
     * cycle's deadline ({@link Watchdog#wakeFor}: woken if that comes before its wake time). One
     * watchdog shared by the executor's tasks, rather than a hook object per task: with
     * thousands of tasks every object a cycle reaches is a cache miss of its own. Call before
     * {@link #begin}.
     *
     * @param watchdog the executor's watchdog
     */
    void watchedBy(Watchdog watchdog) {
        this.watchdog = watchdog;
    }

    /**
     * Before the start instant is taken: what the start needs that does not depend on it, and
     * the anchoring {@link #begin} does, on a provisional instant. An executor that starts
     * thousands of tasks calls it for every one first and times that pass: starting them after
     * the instant takes about as long (the pooled executor puts its instant ahead by it; 10 000
     * pooled tasks took 7-14 ms to start on the development VM, each first release that late).
     *
     * @param stopAllRequest how the executor stops the monitor when a task's policy says
     *     {@link ErrorPolicy#STOP_ALL}; called on the cycle's thread
     * @param zeroCycleSpacingNs how long after its start a continuous cycle that took no world
     *     time is released again: 0 on a real clock, the step executor's idle step on a manual one
     *     (where time only moves if someone moves it)
     */
    void prepareStart(Runnable stopAllRequest, long zeroCycleSpacingNs) {
        this.stopAllRequest = stopAllRequest;
        this.zeroCycleSpacingNs = zeroCycleSpacingNs;
        anchor(Long.MIN_VALUE / 2); // the work of the start, so that timing this pass predicts it
    }

    /** Fixes the grid and the first release on {@code startNs}. */
    private void anchor(long startNs) {
        this.startNs = startNs;
        releases.anchor(index, startNs + offsetNs);
        releases.next(index, 0, startNs + offsetNs);
    }

    /**
     * The start, after {@link #prepareStart}: fixes the grid (release k of a periodic task at
     * {@code startNs + offset + k * period}; a once task at {@code startNs + offset}; a
     * continuous task at {@code startNs}).
     *
     * @param startNs the start instant, the same for every task of the monitor
     */
    void begin(long startNs) {
        anchor(startNs);
        releases.publishPendingIndex(index, release == Release.PERIODIC ? 0L : -1L);
        setState(TaskState.RUNNING, startNs);
    }

    /**
     * @return the world time at which {@link #runCycle()} is due next, or {@link #NEVER}; read
     *     by the thread that runs the task's cycles
     */
    long nextReleaseNs() {
        return releases.nextReleaseNs(index);
    }

    /**
     * @return the absolute deadline of the release {@link #nextReleaseNs()} names, or
     *     {@link #NEVER} if not periodic or not released again; read by the thread that runs the
     *     task's cycles (the pooled executor orders due releases by it)
     */
    long nextDeadlineNs() {
        return release == Release.PERIODIC ? releases.nextDeadlineNs(index) : NEVER;
    }

    /** @return the world time of release k (periodic), or of the single run (once/continuous) */
    long releaseTimeNs(long k) {
        return release == Release.PERIODIC ? releases.releaseNs(index, k) : releases.baseNs(index);
    }

    /** @return the absolute deadline of release k, or {@link Long#MAX_VALUE} if not periodic */
    long deadlineOf(long k) {
        return release == Release.PERIODIC ? releases.deadlineOf(index, k) : Long.MAX_VALUE;
    }

    /**
     * @return the relative deadline, if periodic and it can never change (no adaptive period);
     *     else -1
     */
    long fixedDeadlineNs() {
        return release == Release.PERIODIC && adaptive == null ? releases.deadlineNs(index) : -1;
    }

    /** @return the current period in world nanoseconds (0 unless periodic) */
    long periodNs() {
        return releases.periodNs(index);
    }

    /** @return every period change so far; call only after the task's cycles have stopped */
    List<PeriodChange> periodHistory() {
        return List.copyOf(periodHistory);
    }

    /**
     * For the watchdog, which sleeps until the earliest deadline that could be missed instead of
     * being woken at every cycle start.
     *
     * @return the deadline of the running cycle, or else of the release the task waits for; or
     *     {@link Long#MAX_VALUE} if not periodic or not released again
     */
    long watchDeadlineNs() {
        long running = runningDeadlineNs();
        if (running != Long.MAX_VALUE) {
            return running;
        }
        long k = releases.pendingIndex(index);
        return k < 0 ? Long.MAX_VALUE : deadlineOf(k);
    }

    /**
     * @return the absolute deadline of the cycle running now, or {@link Long#MAX_VALUE} if none
     */
    long runningDeadlineNs() {
        long k = releases.runningCycle(index);
        return k < 0 ? Long.MAX_VALUE : deadlineOf(k);
    }

    /**
     * Runs the due release: copy-in, execute, commit, bookkeeping, then decides the next release
     * ({@link #nextReleaseNs()}), the task's new state, and, under STOP_ALL, asks the executor to
     * stop. Listener faults are contained; only a {@link VirtualMachineError} of the task escapes.
     */
    void runCycle() {
        long k = releases.nextIndex(index);
        long releaseNs = releases.nextReleaseNs(index);
        long cycleStartNs = clock.nanos();
        if (statisticsTable.released(index, Math.max(0, cycleStartNs - releaseNs))) {
            statisticsTable.tryRecordWaiting(index);
        }
        boolean periodic = release == Release.PERIODIC;
        if (periodic) {
            long deadline = deadlineOf(k);
            if (cycleStartNs > deadline) {
                // Started after its deadline (it waited for a thread or a worker): the miss is
                // certain and reported now, as the watchdog would at its next look; nothing for
                // the watchdog to watch, so it is not woken (a backlog would wake it every cycle).
                releases.startCycleAlreadyMissed(index, k);
                statistics.missed();
                events.onDeadlineMiss(this, releaseNs, deadline, cycleStartNs, true);
            } else {
                releases.startCycle(index, k);
                if (watchdog != null) {
                    watchdog.wakeFor(deadline);
                }
            }
        }

        boolean anyNew = false;
        for (int i = 0; i < inputs.length; i++) {
            InputHandle<?> input = inputs[i];
            anyNew |= input.refresh(cycleStartNs);
            inputGenerations[i] = input.generation();
            if (input.isExpired()) {
                statistics.expiredRead();
                events.onExpiredInput(this, input.key().name(), input.ageNs(), input.maxAgeNs(), cycleStartNs);
            }
        }
        if (inputs.length > 0 && !anyNew) {
            statistics.staleRun();
            events.onStaleRun(this, cycleStartNs);
        }

        Throwable failure = null;
        try {
            task.execute(cycleStartNs);
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
                    events.onCommit(this, output.keyIndex(), generation, endNs);
                    events.onCommitValue(this, output.keyIndex(), generation, endNs, output.value());
                }
            }
        } else {
            for (OutputHandle<?> output : outputs) {
                output.discard();
            }
            endNs = clock.nanos();
        }

        boolean missed = false;
        if (periodic && releases.finishCycle(index, k)) {
            // The watchdog had not claimed this cycle: a late finish is reported now.
            long deadline = deadlineOf(k);
            if (endNs > deadline) {
                missed = true;
                statistics.missed();
                events.onDeadlineMiss(this, releaseNs, deadline, endNs, false);
            }
        } else if (periodic) {
            missed = true; // claimed by the watchdog: reported as missed while running
        }
        long execNs = endNs - cycleStartNs;
        if (statisticsTable.cycleEnded(index, execNs)) {
            statisticsTable.tryRecordWaiting(index);
        }
        if (adaptive != null) {
            adaptive.cycleEnded(execNs);
        }
        events.onCycle(this, releaseNs, cycleStartNs, endNs);
        if (failure != null) {
            statistics.error();
            events.onTaskError(this, failure, spec.errorPolicy(), endNs);
        }
        events.onCycleRecord(this, failure != null ? CycleOutcome.ERROR : missed ? CycleOutcome.MISS
                : inputs.length > 0 && !anyNew ? CycleOutcome.STALE : CycleOutcome.OK,
                releaseNs, cycleStartNs, endNs, inputGenerations);
        if (failure != null) {
            switch (spec.errorPolicy()) {
                case DISABLE_TASK -> {
                    neverAgain();
                    setState(TaskState.DISABLED, endNs);
                    return;
                }
                case STOP_ALL -> {
                    neverAgain();
                    stopAllRequest.run();
                    return;
                }
                default -> {
                }
            }
        }
        scheduleNext(k, cycleStartNs, endNs, failure != null);
    }

    /**
     * Releases a continuous task at {@code nowNs}, whatever its own next release, and runs the
     * cycle: a continuous task is released when its previous cycle has ended, and a test that
     * drives it by hand decides when that is. Its next release then follows the usual rule.
     *
     * @param nowNs world time of the release (the clock's time)
     * @throws IllegalStateException if the task is not continuous, or will not be released again
     *     (disabled)
     */
    void releaseNow(long nowNs) {
        if (release != Release.CONTINUOUS) {
            throw new IllegalStateException(OffPathText.notContinuous(name(), spec.schedule().kind()));
        }
        if (releases.nextReleaseNs(index) == NEVER) {
            throw new IllegalStateException(OffPathText.willNotRunAgain(name(), state));
        }
        releases.next(index, releases.nextIndex(index), nowNs);
        runCycle();
    }

    /**
     * After an executor's own fault around {@link #runCycle()} (a framework bug, reported by the
     * executor): releases the task again by the same rules as after a cycle that threw and
     * ended now, so the executor neither spins on the same release nor loses the task.
     *
     * @param nowNs world time
     */
    void recoverAfterFault(long nowNs) {
        long k = releases.nextIndex(index);
        if (release == Release.PERIODIC) {
            releases.finishCycle(index, k);
        }
        scheduleNext(k, Math.min(nowNs, releases.nextReleaseNs(index)), nowNs, true);
    }

    /** The release rules after cycle k, which started at {@code cycleStartNs} and ended at {@code endNs}. */
    private void scheduleNext(long k, long cycleStartNs, long endNs, boolean failed) {
        switch (release) {
            case PERIODIC -> {
                long next = nextAfter(k, endNs);
                releases.next(index, next, releases.releaseNs(index, next));
                releases.publishPendingIndex(index, next);
            }
            case CONTINUOUS -> {
                // Compare with the start, not the release: a zero-duration cycle that started
                // late must still be spaced, or it would run twice at the same instant.
                releases.next(index, k + 1, failed ? endNs + CONTINUOUS_ERROR_PAUSE_NS
                        : endNs > cycleStartNs ? endNs : cycleStartNs + zeroCycleSpacingNs);
            }
            case ONCE -> {
                neverAgain();
                setState(TaskState.FINISHED, endNs);
            }
        }
    }

    private void neverAgain() {
        releases.next(index, releases.nextIndex(index), NEVER);
        releases.publishPendingIndex(index, -1L);
    }

    /**
     * The watchdog's check: if the running cycle is past its deadline, claims it and reports the
     * miss now, while the task is still running.
     *
     * @param nowNs world time
     */
    void checkDeadline(long nowNs) {
        long k = releases.runningCycle(index);
        if (k < 0) {
            return;
        }
        long deadline = deadlineOf(k);
        if (nowNs <= deadline || !releases.claimCycle(index, k)) {
            return;
        }
        statistics.missed();
        events.onDeadlineMiss(this, releaseTimeNs(k), deadline, nowNs, true);
    }

    /**
     * The release to run after release {@code k} whose cycle ended at {@code endNs}
     * ({@link ReleaseTable#nextAfter}); each grid point passed over is counted as a release, a
     * skipped release and a miss. With adaptive periods, this is also where an evaluation window
     * ends and the grid may be re-anchored.
     */
    private long nextAfter(long k, long endNs) {
        long next = releases.nextAfter(index, k, endNs);
        long passed = next - (k + 1);
        if (passed > 0) {
            statistics.skipped(passed);
            events.onSkippedReleases(this, passed, endNs);
        }
        if (adaptive != null) {
            PeriodChange change = adaptive.evaluate(name(), releases.releaseNs(index, next) - startNs,
                    releases.periodNs(index), statistics.releases(), statistics.misses(), statistics.runs(),
                    statistics.staleRuns());
            if (change != null) {
                releases.reanchor(index, next, change.toPeriodNs(), adaptive.deadlineFor(change.toPeriodNs()));
                periodHistory.add(change);
                events.onPeriodChange(this, change, endNs);
            }
        }
        return next;
    }

    void setState(TaskState newState, long nowNs) {
        state = newState;
        events.onStateChange(this, newState, nowNs);
    }

    TaskState state() {
        return state;
    }

    /** Live counters, safe at any time from any thread; allocates (not for task threads). */
    TaskCounters counters() {
        return statistics.counters();
    }

    /** Builds the report; call only after the task's cycles have stopped. */
    TaskReport report() {
        long rel = statistics.releases();
        long miss = statistics.misses();
        boolean periodic = release == Release.PERIODIC;
        Double period = periodic ? releases.periodNs(index) / 1e6 : null;
        Double deadline = periodic ? releases.deadlineNs(index) / 1e6 : null;
        Double offset = periodic ? offsetNs / 1e6 : null;
        return new TaskReport(name(), spec.schedule().kind(), period, deadline, offset, rel, statistics.runs(), miss,
                rel == 0 ? 0.0 : round2(100.0 * miss / rel), statistics.skippedReleases(), statistics.staleRuns(),
                statistics.errors(), statistics.expiredReads(), statistics.execUs(), statistics.latenessUs(),
                statistics.listenerErrors(), null, inputMaxAgesMs());
    }

    /** @return the maximum age the task declared per input key, ms, in declaration order (none: empty) */
    private Map<String, Double> inputMaxAgesMs() {
        Map<String, Double> ages = new LinkedHashMap<>();
        for (InputHandle<?> input : inputs) {
            if (input.maxAgeNs() != Long.MAX_VALUE) {
                ages.put(input.key().name(), input.maxAgeNs() / 1e6);
            }
        }
        return ages;
    }

    static double round2(double v) {
        return Rounding.toDecimals(v, 2);
    }
}
