package io.rtaware.core.time;

/**
 * Wall-clock time in nanoseconds since the Unix epoch, as network protocols stamp samples (ROS 2
 * source timestamps). The epoch offset is taken once, at construction, from the system clock;
 * after that the time advances with {@link System#nanoTime()}, so it has nanosecond resolution,
 * never steps, and reading it allocates nothing. Two instances in one process agree to within the
 * system clock's resolution at their construction. Thread-safe.
 */
public final class EpochClock {

    private final long offsetNs;

    /** Takes the epoch offset now. */
    public EpochClock() {
        java.time.Instant now = java.time.Instant.now();
        long epochNs = now.getEpochSecond() * 1_000_000_000L + now.getNano();
        offsetNs = epochNs - System.nanoTime();
    }

    /** @return nanoseconds since 1970-01-01T00:00Z */
    public long epochNanos() {
        return System.nanoTime() + offsetNs;
    }
}
