package io.rtaware.core.monitor;

/**
 * How the monitor moves an adaptive task's period inside its declared range
 * ({@link io.rtaware.core.task.Schedule.Periodic#isAdaptive()}). The evidence is gathered per
 * evaluation window of {@code windowReleases} releases of the task; at the end of each window:
 * <ol>
 *   <li>any miss in the window: the period becomes longer (reason {@code MISSES});</li>
 *   <li>otherwise, if the task has inputs and at least {@code staleLongerPct}% of the window's
 *   runs were stale: longer (reason {@code STALE}, the task runs faster than its data);</li>
 *   <li>otherwise, if at most {@code staleShorterPct}% of the runs were stale (inputs are fresh
 *   almost every time, or the task has no inputs) and the window's longest execution time is at
 *   most {@code headroomPct}% of the shorter period: shorter (reason
 *   {@code FRESH_WITH_HEADROOM});</li>
 *   <li>otherwise the period stays.</li>
 * </ol>
 * Longer multiplies the period by {@code stepFactor}, shorter divides by it, both rounded to a
 * whole microsecond and clamped to the range; a move that the clamp cancels is not a change.
 * The band between the two stale thresholds is the hysteresis: a consumer sampling its input at
 * twice the input's rate sees about 50% stale runs and stays put. Immutable.
 *
 * @param windowReleases releases per evaluation window, at least 1
 * @param stepFactor factor of one step, greater than 1
 * @param staleLongerPct stale share (percent of runs) from which the period grows
 * @param staleShorterPct stale share (percent of runs) up to which the period may shrink
 * @param headroomPct longest execution time in the window, as percent of the shorter period, up
 *     to which the period may shrink
 */
public record AdaptivePolicy(int windowReleases, double stepFactor, double staleLongerPct,
                             double staleShorterPct, double headroomPct) {

    /**
     * Validates the parameters.
     *
     * @param windowReleases releases per evaluation window, at least 1
     * @param stepFactor factor of one step, greater than 1
     * @param staleLongerPct stale share (percent of runs) from which the period grows
     * @param staleShorterPct stale share (percent of runs) up to which the period may shrink
     * @param headroomPct longest execution time in the window, as percent of the shorter period, up to which
     *     the period may shrink
     */
    public AdaptivePolicy {
        if (windowReleases < 1 || !(stepFactor > 1) || !(staleShorterPct < staleLongerPct) || !(headroomPct > 0)) {
            throw new IllegalArgumentException("invalid adaptive policy: window " + windowReleases + ", step "
                    + stepFactor + ", stale " + staleShorterPct + ".." + staleLongerPct + "%, headroom "
                    + headroomPct + "%");
        }
    }

    /** @return window 20 releases, step x1.25, stale band 25..75%, headroom 50% */
    public static AdaptivePolicy defaults() {
        return new AdaptivePolicy(20, 1.25, 75, 25, 50);
    }
}
