package io.rtaware.core.time;

/**
 * World time equal to wall time: {@link System#nanoTime()}. Stateless and thread-safe.
 */
public final class SystemClock implements Clock {

    @Override
    public long nanos() {
        return System.nanoTime();
    }

    @Override
    public String toString() {
        return "SystemClock";
    }
}
