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
     * @param scale world nanoseconds per wall nanosecond; must be positive and finite
     * @throws IllegalArgumentException if the scale is not positive and finite
     */
    public ScaledClock(double scale) {
        if (!(scale > 0) || Double.isInfinite(scale)) {
            throw new IllegalArgumentException("time scale must be positive and finite, got " + scale);
        }
        this.scale = scale;
        this.wallOriginNs = System.nanoTime();
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
        return "ScaledClock(x" + scale + ")";
    }
}
