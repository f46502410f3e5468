package io.rtaware.core.monitor;

import io.rtaware.core.report.Percentiles;
import io.rtaware.core.report.TaskReport;
import io.rtaware.core.task.ErrorPolicy;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.Clock;
import java.util.concurrent.atomic.AtomicLong;
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
 *   <li>a cycle whose inputs had no new data is a stale run (tasks without inputs never are).</li>
 * </ul>
 *
 * <p>Thread-safety: {@link #runCycle} and {@link #nextIndexAfter} are called by the task's own
 * thread only; {@link #checkDeadline(long)} by the watchdog, concurrently, coordinated with the
 * task thread through one atomic cycle token. Counters are safe to read at any time; the
 * histograms only after the task thread has stopped.
 */
final class TaskRuntime implements TaskInfo {

    /** Result of one cycle, telling the executor what to do next. */
    enum Outcome { CONTINUE, DISABLE, STOP_ALL }

    private static final long HIGHEST_TRACKABLE_NS = 3_600_000_000_000L;

    private final TaskSpec spec;
    private final int index;
    private final Clock clock;
    private MonitorListener[] listeners;
    private final InputHandle<?>[] inputs;
    private final OutputHandle<?>[] outputs;
    private final boolean periodic;
    private final long periodNs;
    private final long deadlineNs;
    private final long offsetNs;
    private long baseNs;

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
    private long latenessMaxNs;
    /** End of the latest cycle; task thread only. */
    private long lastCycleEndNs;
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
            periodNs = p.periodNs();
            deadlineNs = p.deadlineNs();
            offsetNs = p.offsetNs();
        } else {
            periodic = false;
            periodNs = 0;
            deadlineNs = 0;
            offsetNs = schedule instanceof Schedule.Once o ? o.offsetNs() : 0;
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
        baseNs = startNs + offsetNs;
        setState(TaskState.RUNNING, startNs);
    }

    /** @return the world time of release k (periodic), or of the single run (once/continuous) */
    long releaseTimeNs(long k) {
        return periodic ? baseNs + k * periodNs : baseNs;
    }

    /** @return the absolute deadline of release k, or {@link Long#MAX_VALUE} if not periodic */
    long deadlineOf(long k) {
        return periodic ? baseNs + k * periodNs + deadlineNs : Long.MAX_VALUE;
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
        record(execNs, exec);
        execSumNs += exec;
        if (exec > execMaxNs) {
            execMaxNs = exec;
        }
        for (MonitorListener l : listeners) {
            l.onCycle(this, releaseNs, startNs, endNs);
        }
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
     * @return true if a miss was reported
     */
    boolean checkDeadline(long nowNs) {
        long token = cycleToken.get();
        if ((token & 1) == 0) {
            return false;
        }
        long k = (token - 1) >>> 1;
        long deadline = deadlineOf(k);
        if (nowNs <= deadline || !cycleToken.compareAndSet(token, token + 1)) {
            return false;
        }
        misses.incrementAndGet();
        for (MonitorListener l : listeners) {
            l.onDeadlineMiss(this, releaseTimeNs(k), deadline, nowNs, true);
        }
        return true;
    }

    /**
     * The release to run after release {@code k} whose cycle ended at {@code endNs}: the next grid
     * point, or, if the cycle overran, the first grid point at or after its end. Each grid point
     * passed over is counted as a release, a skipped release and a miss.
     *
     * @param k the release just run
     * @param endNs when its cycle ended
     * @return the index of the next release to run
     */
    long nextIndexAfter(long k, long endNs) {
        long next = k + 1;
        long since = endNs - baseNs;
        if (since > next * periodNs) {
            long first = Math.floorDiv(since + periodNs - 1, periodNs); // ceil: first grid point >= end
            long passed = first - next;
            releases.addAndGet(passed);
            skipped.addAndGet(passed);
            misses.addAndGet(passed);
            for (MonitorListener l : listeners) {
                l.onSkippedReleases(this, passed, endNs);
            }
            next = first;
        }
        return next;
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

    /** Live counters, safe at any time. */
    TaskCounters counters() {
        return new TaskCounters(releases.get(), runs.get(), misses.get(), skipped.get(), staleRuns.get(),
                errors.get(), expiredReads.get());
    }

    /** Builds the report; call only after the task thread has stopped. */
    TaskReport report() {
        long rel = releases.get();
        long miss = misses.get();
        Double period = periodic ? periodNs / 1e6 : null;
        Double deadline = periodic ? deadlineNs / 1e6 : null;
        return new TaskReport(name(), spec.schedule().kind(), period, deadline, rel, runs.get(), miss,
                rel == 0 ? 0.0 : round2(100.0 * miss / rel), skipped.get(), staleRuns.get(), errors.get(),
                expiredReads.get(), Percentiles.ofNanos(execNs, execMaxNs, execSumNs),
                Percentiles.ofNanos(latenessNs, latenessMaxNs, latenessSumNs));
    }

    static double round2(double v) {
        return Math.round(v * 100.0) / 100.0;
    }
}
