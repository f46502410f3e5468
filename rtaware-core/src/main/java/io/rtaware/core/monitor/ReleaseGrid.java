package io.rtaware.core.monitor;

/**
 * Where the releases of one periodic task lie: release k is at
 * {@code baseNs + (k - baseIndex) * periodNs}, its deadline {@code deadlineNs} later.
 *
 * <p>The grid is fixed at the start ({@link #anchoredAt}) and replaced, never mutated, when an
 * adaptive period changes ({@link #reanchoredAt}): release {@code n} stays where the old grid
 * put it and the releases after it follow the new period. Immutable, so the task's thread can
 * hand a new grid to the watchdog through one volatile field.
 *
 * @param baseIndex the release index at {@code baseNs}
 * @param baseNs the grid's anchor in world time
 * @param periodNs the period (0 for tasks without a period)
 * @param deadlineNs the relative deadline (0 for tasks without a period)
 */
record ReleaseGrid(long baseIndex, long baseNs, long periodNs, long deadlineNs) {

    /**
     * @param startNs the start instant plus the task's offset: release 0
     * @return this grid anchored with release 0 at {@code startNs}
     */
    ReleaseGrid anchoredAt(long startNs) {
        return new ReleaseGrid(0, startNs, periodNs, deadlineNs);
    }

    /**
     * @param n the release that keeps its time
     * @param newPeriodNs the period after it
     * @param newDeadlineNs the relative deadline after it
     * @return a grid on which release {@code n + j} is at {@code releaseNs(n) + j * newPeriodNs}
     */
    ReleaseGrid reanchoredAt(long n, long newPeriodNs, long newDeadlineNs) {
        return new ReleaseGrid(n, releaseNs(n), newPeriodNs, newDeadlineNs);
    }

    /** @return the world time of release {@code k} */
    long releaseNs(long k) {
        return baseNs + (k - baseIndex) * periodNs;
    }

    /** @return the absolute deadline of release {@code k} */
    long deadlineOf(long k) {
        return releaseNs(k) + deadlineNs;
    }

    /**
     * The skip rule: the release after release {@code k} whose cycle ended at {@code endNs} is
     * the next grid point, or, if the cycle overran it, the first grid point at or after the end.
     *
     * @param k the release just run
     * @param endNs when its cycle ended
     * @return the index of the next release to run ({@code k + 1} unless releases were skipped)
     */
    long nextAfter(long k, long endNs) {
        long next = k + 1;
        long since = endNs - baseNs;
        if (since > (next - baseIndex) * periodNs) {
            // ceil: the first grid point >= end
            return baseIndex + Math.floorDiv(since + periodNs - 1, periodNs);
        }
        return next;
    }

    // The record's generated equals, hashCode and toString keep the component names as a string
    // constant, which a C2 compile of any of this class's methods, asked for by a cycle in steady
    // state, would resolve on the cycle's thread (see OffPathText): written out, they keep none.

    @Override
    public boolean equals(Object other) {
        return other instanceof ReleaseGrid g && g.baseIndex == baseIndex && g.baseNs == baseNs
                && g.periodNs == periodNs && g.deadlineNs == deadlineNs;
    }

    @Override
    public int hashCode() {
        return Long.hashCode(baseIndex) + 31 * (Long.hashCode(baseNs) + 31 * (Long.hashCode(periodNs)
                + 31 * Long.hashCode(deadlineNs)));
    }

    @Override
    public String toString() {
        return OffPathText.releaseGrid(this);
    }
}
