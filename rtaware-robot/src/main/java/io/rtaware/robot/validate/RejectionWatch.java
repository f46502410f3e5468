package io.rtaware.robot.validate;

/**
 * Turns persistent rejection into a fault: a device whose samples have all been rejected for
 * at least {@code faultAfterNs} of world time (from the first rejected sample with no accepted
 * sample since) has failed, and acting on it would mean driving blind. A single bad sample, or
 * bad samples mixed with good ones, is not a fault: the good ones are committed. Not
 * thread-safe: one data task owns it.
 */
public final class RejectionWatch {

    private static final long NONE = Long.MIN_VALUE;

    private final long faultAfterNs;
    private long rejectingSinceNs = NONE;

    /**
     * @param faultAfterNs world time of rejection-only samples that makes a fault (> 0)
     * @throws IllegalArgumentException if not positive
     */
    public RejectionWatch(long faultAfterNs) {
        if (faultAfterNs <= 0) {
            throw new IllegalArgumentException("faultAfterNs must be positive, got " + faultAfterNs);
        }
        this.faultAfterNs = faultAfterNs;
    }

    /**
     * Called once per cycle with the device's state.
     *
     * @param nowNs world time now
     * @param newestRejected true if the device's newest sample was rejected
     * @return true if the device has delivered only rejected samples for {@code faultAfterNs}
     */
    public boolean observe(long nowNs, boolean newestRejected) {
        if (!newestRejected) {
            rejectingSinceNs = NONE;
            return false;
        }
        if (rejectingSinceNs == NONE) {
            rejectingSinceNs = nowNs;
        }
        return nowNs - rejectingSinceNs >= faultAfterNs;
    }

    /** @return world time since when only rejected samples came, or {@link Long#MIN_VALUE} */
    public long rejectingSinceNs() {
        return rejectingSinceNs;
    }

    /** Forgets the current streak (e.g. after a reconnection). */
    public void reset() {
        rejectingSinceNs = NONE;
    }
}
