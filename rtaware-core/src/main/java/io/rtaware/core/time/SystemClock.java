package io.rtaware.core.time;

/**
 * World time equal to wall time: {@link System#nanoTime()}. Stateless and thread-safe.
 */
public final class SystemClock implements Clock {

    @Override
    public long nanos() {
        return System.nanoTime();
    }

    /**
     * @return {@code SystemClock}, from the class's name: a string constant here would be
     *     resolved, and allocated, on the release thread whose call of {@link #nanos()} has it
     *     compiled by C2 (see {@code ReleasePathConstantsTest})
     */
    @Override
    public String toString() {
        return getClass().getSimpleName();
    }
}
