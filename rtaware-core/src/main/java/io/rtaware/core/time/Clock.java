package io.rtaware.core.time;

/**
 * The source of world time for everything in rtaware: tasks, monitor, simulator.
 *
 * <p>World time is monotonic nanoseconds from an arbitrary origin. With a {@link ScaledClock}
 * world time runs {@link #timeScale()} times faster than wall time, which is how a slower
 * on-board computer is emulated: every task's computation weighs K times more against its
 * period. Nothing outside the clock and executor code reads {@code System.nanoTime} directly.
 *
 * <p>Implementations are thread-safe.
 */
public interface Clock {

    /**
     * The clock a program runs on for a given time scale: wall time itself at 1, otherwise a
     * {@link ScaledClock} starting at zero.
     *
     * @param timeScale world seconds per wall second; positive and finite
     * @return a {@link SystemClock} for 1, a {@link ScaledClock} otherwise
     * @throws IllegalArgumentException if the scale is not positive and finite
     */
    static Clock forTimeScale(double timeScale) {
        return timeScale == 1.0 ? new SystemClock() : new ScaledClock(timeScale);
    }

    /** @return world time in nanoseconds; never decreases. */
    long nanos();

    /** @return how many nanoseconds of world time pass per nanosecond of wall time. */
    default double timeScale() {
        return 1.0;
    }

    /**
     * Converts a span of world time into the wall time a thread must wait for it.
     *
     * @param worldNs a world-time span in nanoseconds
     * @return the equivalent wall-time span in nanoseconds
     */
    default long toWallNanos(long worldNs) {
        double scale = timeScale();
        return scale == 1.0 ? worldNs : (long) (worldNs / scale);
    }
}
