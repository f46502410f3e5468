package io.rtaware.core.monitor;

import io.rtaware.core.time.Clock;
import java.util.concurrent.locks.LockSupport;

/**
 * Waits on a real (or scaled) clock with {@link LockSupport#parkNanos}, for the wall time the
 * clock says is left (never {@code Thread.sleep}, which rounds to whole milliseconds on JDK 17).
 * Thread-safe, allocation-free.
 */
final class ParkingClockWaiter implements ClockWaiter {

    /** Longest single park: a waiter with nothing due still looks around this often. */
    private static final long MAX_PARK_NS = 100_000_000L;

    private final Clock clock;

    ParkingClockWaiter(Clock clock) {
        this.clock = clock;
    }

    @Override
    public void register(int party, Thread thread) {
        // Nothing to track: wall time moves by itself.
    }

    @Override
    public void park(int party, long targetNs) {
        if (targetNs == Long.MAX_VALUE) {
            LockSupport.parkNanos(MAX_PARK_NS);
            return;
        }
        long remainingNs = targetNs - clock.nanos();
        if (remainingNs > 0) {
            LockSupport.parkNanos(Math.max(1, clock.toWallNanos(remainingNs)));
        }
    }

    @Override
    public void wake(int party, Thread thread) {
        LockSupport.unpark(thread);
    }

    @Override
    public void done(int party) {
        // Nothing to track.
    }

    @Override
    public long zeroCycleSpacingNs() {
        return 0;
    }

    @Override
    public void close() {
        // Holds nothing.
    }
}
