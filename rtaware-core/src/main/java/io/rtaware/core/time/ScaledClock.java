package io.rtaware.core.time;

/**
 * World time that runs {@code scale} times faster than wall time, starting at zero when the
 * clock is created. A scale of 10 makes one wall second ten world seconds: a task whose
 * computation takes 1 ms of wall time then weighs 10 ms against its world-time period.
 * Immutable and thread-safe.
 */
public final class ScaledClock implements Clock {

    private final double scale;
    private final long wallOriginNs;
    /**
     * {@link #toString()}'s text, built here: {@link #nanos()} runs every release, and before
     * HotSpot compiles it with C2 it resolves every string constant of this class on the release
     * thread that asked (see {@code ReleasePathConstantsTest}).
     */
    private final String description;

    /**
     * @param scale world nanoseconds per wall nanosecond; must be positive and finite
     * @throws IllegalArgumentException if the scale is not positive and finite
     */
    public ScaledClock(double scale) {
        if (!(scale > 0) || Double.isInfinite(scale)) {
            throw new IllegalArgumentException(CheckText.badScale(scale));
        }
        this.scale = scale;
        this.wallOriginNs = System.nanoTime();
        this.description = "ScaledClock(x" + scale + ")";
    }

    /**
     * The argument check's text, in a class of its own: a message built only when the check fails
     * stays unresolved in this class's constants, to be resolved on a release thread (see
     * {@link #description}).
     */
    private static final class CheckText {
        static String badScale(double scale) {
            return "time scale must be positive and finite, got " + scale;
        }
    }

    @Override
    public long nanos() {
        return (long) ((System.nanoTime() - wallOriginNs) * scale);
    }

    @Override
    public double timeScale() {
        return scale;
    }

    @Override
    public String toString() {
        return description;
    }
}
