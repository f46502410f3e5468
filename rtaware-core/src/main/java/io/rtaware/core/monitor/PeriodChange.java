package io.rtaware.core.monitor;

/**
 * One change of an adaptive task's period, with the evidence of the window that caused it.
 * The new period applies from {@code sinceStartNs} on: release j after the change is at
 * {@code start + sinceStartNs + j * toPeriodNs}. Immutable.
 *
 * @param task the task's name
 * @param sinceStartNs when the new grid starts (its first release), world time since the
 *     monitor's start
 * @param fromPeriodNs the period before
 * @param toPeriodNs the period after
 * @param reason why
 * @param windowReleases releases in the evaluation window
 * @param windowMisses misses in the window
 * @param windowRuns runs in the window
 * @param windowStaleRuns stale runs in the window
 * @param windowExecMaxNs longest execution time in the window
 */
public record PeriodChange(String task, long sinceStartNs, long fromPeriodNs, long toPeriodNs, Reason reason,
                           long windowReleases, long windowMisses, long windowRuns, long windowStaleRuns,
                           long windowExecMaxNs) {

    /** Why a period changed; see {@link AdaptivePolicy}. */
    public enum Reason {
        /** The window had deadline misses: longer. */
        MISSES,
        /** Most runs of the window found no new input: longer. */
        STALE,
        /** Inputs were fresh and execution left headroom: shorter. */
        FRESH_WITH_HEADROOM
    }
}
