package io.rtaware.core.monitor;

import io.rtaware.core.time.ManualClock;
import java.util.Collection;
import java.util.List;

/**
 * Runs tasks one cycle at a time on a {@link ManualClock}, for exact tests of the timing rules:
 * no threads, no sleeping, same result every time. It only waits and calls (see
 * {@link Executor}): "waiting" is advancing the manual clock to the earliest due release; every
 * rule of what a cycle means is the {@link TaskRuntime}'s, the same as on real threads.
 *
 * <p>Tasks run one at a time, like tasks sharing one core: the due release with the earliest
 * time runs first (ties in registration order). A task simulates its execution time by
 * advancing the clock inside its cycle; the deadline watchdog observes every advance, so a miss
 * is reported at the deadline while the cycle is still running. A continuous task is released
 * again when its cycle returns; if that cycle took no world time, it is released again
 * {@link #idleStepNs()} later so that stepping always makes progress.
 *
 * <p>The next due release is found in a {@link TaskHeap} keyed by release time and slot, so a
 * step costs O(log n) in the number of tasks, not a scan of all of them: stepping 10 000 tasks
 * measures the per-release bookkeeping (as {@code MonitorBench} does), not the search. A task's
 * next release changes only in its own cycle, where the step puts it back with its new key, or
 * by {@link #releaseNow}, after which the heap is rebuilt.
 *
 * <p>Not thread-safe: one test thread drives it.
 */
public final class StepExecutor implements Executor {

    /** The idle step of zero-duration continuous cycles. */
    static final long DEFAULT_IDLE_STEP_NS = 1_000_000;

    private final ManualClock clock;
    private final TaskRuntime[] runtimes;
    private final Runnable stop;
    private final FrameworkFaults faults;
    /** Every task whose next release is not {@link TaskRuntime#NEVER}, by that release, ties by slot. */
    private final TaskHeap due;
    /** True after {@link #releaseNow}: a task's release moved outside its step, the heap is rebuilt. */
    private boolean dueStale;
    private TaskRuntime current;
    private Runnable unsubscribe;
    private boolean stopped;

    StepExecutor(ManualClock clock, List<TaskRuntime> runtimes, Runnable stop, FrameworkFaults faults) {
        this.clock = clock;
        this.runtimes = runtimes.toArray(new TaskRuntime[0]);
        this.stop = stop;
        this.faults = faults;
        this.due = new TaskHeap(this.runtimes.length);
    }

    /** @return world time a zero-duration continuous cycle waits before its next release */
    public long idleStepNs() {
        return DEFAULT_IDLE_STEP_NS;
    }

    @Override
    public long start() {
        for (TaskRuntime runtime : runtimes) {
            runtime.prepareStart(stop, idleStepNs());
        }
        long startNs = clock.nanos();
        unsubscribe = clock.onAdvance((fromNs, toNs) -> {
            TaskRuntime running = current;
            if (running != null) {
                running.checkDeadline(toNs);
            }
        });
        for (TaskRuntime runtime : runtimes) {
            runtime.begin(startNs);
        }
        rebuildDue();
        return startNs;
    }

    /**
     * Runs the next due cycle, advancing the clock to its release if needed.
     *
     * @return false if no task is left to release, or the monitor was stopped
     */
    public boolean step() {
        if (stopped || !dueBefore(TaskRuntime.NEVER)) {
            return false;
        }
        runNext();
        return true;
    }

    /**
     * Runs every cycle released before {@code endNs}, then advances the clock to {@code endNs}.
     *
     * @param endNs world time to run until
     */
    public void runUntil(long endNs) {
        while (!stopped && dueBefore(endNs)) {
            runNext();
        }
        clock.advanceTo(endNs);
    }

    /**
     * @param durationNs world time to run for, from now
     */
    public void runFor(long durationNs) {
        runUntil(clock.nanos() + durationNs);
    }

    /**
     * Releases a continuous task now, outside the order of {@link #step()}, and runs one cycle of
     * it with its real inputs and outputs: for tests that drive a task by hand (see
     * {@code io.rtaware.core.testing.TaskHarness}). Every rule of the cycle applies as usual.
     *
     * @param task the task's name
     * @throws IllegalArgumentException if there is no such task
     * @throws IllegalStateException if it is not continuous, is disabled, or the monitor stopped
     */
    public void releaseNow(String task) {
        if (stopped) {
            throw new IllegalStateException("the monitor has stopped");
        }
        TaskRuntime chosen = null;
        for (TaskRuntime runtime : runtimes) {
            if (runtime.name().equals(task)) {
                chosen = runtime;
            }
        }
        if (chosen == null) {
            throw new IllegalArgumentException("no task '" + task + "'");
        }
        current = chosen;
        try {
            chosen.releaseNow(clock.nanos());
        } finally {
            current = null;
            dueStale = true;
        }
    }

    /** @return whether the earliest next release (ties: the lowest slot) is before {@code limitNs} */
    private boolean dueBefore(long limitNs) {
        if (dueStale) {
            rebuildDue();
        }
        return due.size() > 0 && due.peekKey() < limitNs;
    }

    /** Queues every task that will be released again, by its next release. */
    private void rebuildDue() {
        due.clear();
        for (int slot = 0; slot < runtimes.length; slot++) {
            long next = runtimes[slot].nextReleaseNs();
            if (next != TaskRuntime.NEVER) {
                due.push(slot, next);
            }
        }
        dueStale = false;
    }

    /** Runs the task at the top of the heap, then queues it again by its new next release. */
    private void runNext() {
        int slot = due.pop();
        TaskRuntime runtime = runtimes[slot];
        clock.advanceTo(runtime.nextReleaseNs());
        current = runtime;
        try {
            Executor.runCycle(runtime, clock, faults);
        } finally {
            current = null;
            long next = runtime.nextReleaseNs();
            // A releaseNow inside the cycle marked the heap for a rebuild, which queues this task too.
            if (!dueStale && next != TaskRuntime.NEVER) {
                due.push(slot, next);
            }
        }
    }

    @Override
    public void stopReleasing() {
        stopped = true;
    }

    /** Nothing to wait for: every cycle runs on the thread that steps this executor, between its steps. */
    @Override
    public void joinThreadsOf(Collection<TaskRuntime> tasks) {
    }

    /** No thread of its own: its cycles run on the thread that steps it. */
    @Override
    public boolean runsCyclesOn(Thread thread) {
        return false;
    }

    @Override
    public void stopAndJoin() {
        stopped = true;
        if (unsubscribe != null) {
            unsubscribe.run();
        }
    }
}
