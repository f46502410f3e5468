package io.rtaware.core.monitor;

import io.rtaware.core.time.ManualClock;
import java.util.List;

/**
 * Runs tasks one cycle at a time on a {@link ManualClock}, for exact tests of the timing rules:
 * no threads, no sleeping, same result every time.
 *
 * <p>Tasks run one at a time, like tasks sharing one core: the due release with the earliest
 * time runs first (ties in registration order). A task simulates its execution time by
 * advancing the clock inside its cycle; the deadline watchdog observes every advance, so a miss
 * is reported at the deadline while the cycle is still running. A continuous task is released
 * again when its cycle returns; if that cycle took no world time, it is released again
 * {@link #idleStepNs()} later so that stepping always makes progress.
 *
 * <p>Not thread-safe: one test thread drives it.
 */
public final class StepExecutor implements Monitor.Executor {

    private static final long DEFAULT_IDLE_STEP_NS = 1_000_000;

    private final ManualClock clock;
    private final List<TaskRuntime> runtimes;
    private final Monitor monitor;
    private final long[] nextIndex;
    private final long[] nextReleaseNs;
    private TaskRuntime current;
    private Runnable unsubscribe;
    private boolean stopped;

    StepExecutor(ManualClock clock, List<TaskRuntime> runtimes, Monitor monitor) {
        this.clock = clock;
        this.runtimes = runtimes;
        this.monitor = monitor;
        this.nextIndex = new long[runtimes.size()];
        this.nextReleaseNs = new long[runtimes.size()];
    }

    /** @return world time a zero-duration continuous cycle waits before its next release */
    public long idleStepNs() {
        return DEFAULT_IDLE_STEP_NS;
    }

    @Override
    public long start() {
        long startNs = clock.nanos();
        unsubscribe = clock.onAdvance((fromNs, toNs) -> {
            TaskRuntime running = current;
            if (running != null) {
                running.checkDeadline(toNs);
            }
        });
        for (TaskRuntime runtime : runtimes) {
            runtime.begin(startNs);
            nextReleaseNs[runtime.index()] = runtime.releaseTimeNs(0);
        }
        return startNs;
    }

    /**
     * Runs the next due cycle, advancing the clock to its release if needed.
     *
     * @return false if no task is left to release, or the monitor was stopped
     */
    public boolean step() {
        int chosen = -1;
        for (int i = 0; i < runtimes.size(); i++) {
            if (nextReleaseNs[i] != Long.MAX_VALUE && (chosen < 0 || nextReleaseNs[i] < nextReleaseNs[chosen])) {
                chosen = i;
            }
        }
        if (chosen < 0 || stopped) {
            return false;
        }
        runOne(runtimes.get(chosen));
        return true;
    }

    /**
     * Runs every cycle released before {@code endNs}, then advances the clock to {@code endNs}.
     *
     * @param endNs world time to run until
     */
    public void runUntil(long endNs) {
        while (!stopped) {
            int chosen = -1;
            for (int i = 0; i < runtimes.size(); i++) {
                if (nextReleaseNs[i] < endNs && (chosen < 0 || nextReleaseNs[i] < nextReleaseNs[chosen])) {
                    chosen = i;
                }
            }
            if (chosen < 0) {
                break;
            }
            runOne(runtimes.get(chosen));
        }
        clock.advanceTo(endNs);
    }

    /**
     * @param durationNs world time to run for, from now
     */
    public void runFor(long durationNs) {
        runUntil(clock.nanos() + durationNs);
    }

    private void runOne(TaskRuntime runtime) {
        int i = runtime.index();
        long k = nextIndex[i];
        long releaseNs = nextReleaseNs[i];
        clock.advanceTo(releaseNs);
        long startNs = clock.nanos(); // later than the release if another cycle ran past it
        current = runtime;
        TaskRuntime.Outcome outcome;
        try {
            outcome = runtime.runCycle(k, releaseNs);
        } finally {
            current = null;
        }
        long endNs = runtime.lastCycleEndNs();
        switch (outcome) {
            case DISABLE -> {
                runtime.setState(TaskState.DISABLED, endNs);
                nextReleaseNs[i] = Long.MAX_VALUE;
                return;
            }
            case STOP_ALL -> {
                nextReleaseNs[i] = Long.MAX_VALUE;
                monitor.stop();
                return;
            }
            default -> {
            }
        }
        switch (runtime.schedule().kind()) {
            case "periodic" -> {
                long next = runtime.nextIndexAfter(k, endNs);
                nextIndex[i] = next;
                nextReleaseNs[i] = runtime.releaseTimeNs(next);
            }
            case "continuous" -> {
                nextIndex[i] = k + 1;
                // Compare with the start, not the release: a zero-duration cycle that started late
                // must still wait one idle step, or it would run twice at the same instant.
                nextReleaseNs[i] = endNs > startNs ? endNs : endNs + idleStepNs();
            }
            default -> {
                runtime.setState(TaskState.FINISHED, endNs);
                nextReleaseNs[i] = Long.MAX_VALUE;
            }
        }
    }

    @Override
    public void stopAndJoin() {
        stopped = true;
        if (unsubscribe != null) {
            unsubscribe.run();
        }
    }
}
