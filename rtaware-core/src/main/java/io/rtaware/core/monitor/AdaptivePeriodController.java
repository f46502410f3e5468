package io.rtaware.core.monitor;

import io.rtaware.core.task.Schedule;

/**
 * Applies an {@link AdaptivePolicy} to one task: gathers the evidence of each evaluation window
 * from the task's running totals and, when a window is full, decides whether the period moves.
 * The caller re-anchors the release grid with the decision.
 *
 * <p>Task thread only; allocates only when the period changes (the {@link PeriodChange}).
 */
final class AdaptivePeriodController {

    private final AdaptivePolicy policy;
    private final Schedule.Periodic declared;
    private final boolean hasInputs;
    private long windowReleases;
    private long windowMisses;
    private long windowRuns;
    private long windowStale;
    private long windowExecMaxNs;

    /**
     * @param policy the rule
     * @param declared the task's schedule, with its period range
     * @param hasInputs whether the task consumes data (the stale rules need inputs)
     */
    AdaptivePeriodController(AdaptivePolicy policy, Schedule.Periodic declared, boolean hasInputs) {
        this.policy = policy;
        this.declared = declared;
        this.hasInputs = hasInputs;
    }

    /** @param execNs the execution time of a cycle that just ended */
    void cycleEnded(long execNs) {
        if (execNs > windowExecMaxNs) {
            windowExecMaxNs = execNs;
        }
    }

    /**
     * Ends the evaluation window if it is full.
     *
     * @param task the task's name (for the change record)
     * @param sinceStartNs world time of the release from which a new period would apply, since start
     * @param periodNs the current period
     * @param releases the task's releases so far
     * @param misses its misses so far
     * @param runs its runs so far
     * @param staleRuns its stale runs so far
     * @return the change to apply, or null if the window is not full or the period stays
     */
    PeriodChange evaluate(String task, long sinceStartNs, long periodNs, long releases, long misses, long runs,
                          long staleRuns) {
        long rel = releases - windowReleases;
        if (rel < policy.windowReleases()) {
            return null;
        }
        long miss = misses - windowMisses;
        long ran = runs - windowRuns;
        long stale = staleRuns - windowStale;
        long execMax = windowExecMaxNs;
        windowReleases += rel;
        windowMisses += miss;
        windowRuns += ran;
        windowStale += stale;
        windowExecMaxNs = 0;

        long longer = Math.min(declared.maxPeriodNs(), roundToMicros(periodNs * policy.stepFactor()));
        long shorter = Math.max(declared.minPeriodNs(), roundToMicros(periodNs / policy.stepFactor()));
        long target = periodNs;
        PeriodChange.Reason reason = null;
        if (miss > 0) {
            target = longer;
            reason = PeriodChange.Reason.MISSES;
        } else if (hasInputs && stale * 100.0 >= policy.staleLongerPct() * ran) {
            target = longer;
            reason = PeriodChange.Reason.STALE;
        } else if ((!hasInputs || stale * 100.0 <= policy.staleShorterPct() * ran)
                && execMax * 100.0 <= policy.headroomPct() * shorter) {
            target = shorter;
            reason = PeriodChange.Reason.FRESH_WITH_HEADROOM;
        }
        if (target == periodNs) {
            return null;
        }
        return new PeriodChange(task, sinceStartNs, periodNs, target, reason, rel, miss, ran, stale, execMax);
    }

    /** @return the relative deadline that goes with {@code periodNs} under the declared schedule */
    long deadlineFor(long periodNs) {
        return declared.withPeriod(periodNs).deadlineNs();
    }

    private static long roundToMicros(double ns) {
        return Math.max(1_000, Math.round(ns / 1_000) * 1_000);
    }
}
