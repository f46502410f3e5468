package io.rtaware.core.monitor;

import io.rtaware.core.time.Clock;
import io.rtaware.core.time.MonotonicSleeper;
import java.util.concurrent.locks.LockSupport;

/**
 * Waits on a real (or scaled) clock with {@link LockSupport#parkNanos}, for the wall time the
 * clock says is left (never {@code Thread.sleep}, which rounds to whole milliseconds on JDK 17);
 * a party nobody wakes may instead sleep with a {@link MonotonicSleeper} ({@link Party#sleep}).
 * Thread-safe, allocation-free.
 */
final class ParkingClockWaiter implements ClockWaiter {

    /** Longest single park: a waiter with nothing due still looks around this often. */
    private static final long MAX_PARK_NS = 100_000_000L;

    private final Clock clock;
    /** Null: {@link Party#sleep} parks like {@link Party#park}. */
    private final MonotonicSleeper sleeper;

    /**
     * @param clock the world clock
     * @param sleeper what {@link Party#sleep} uses, or null to park there too
     */
    ParkingClockWaiter(Clock clock, MonotonicSleeper sleeper) {
        this.clock = clock;
        this.sleeper = sleeper;
    }

    @Override
    public Party register(Thread thread) {
        return new ParkingParty(thread);
    }

    /** A thread that parks for the wall time left; nothing to track, wall time moves by itself. */
    private final class ParkingParty implements Party {
        /** Null until the first wait of a party registered without its thread. */
        private volatile Thread thread;

        ParkingParty(Thread thread) {
            this.thread = thread;
        }

        @Override
        public void park(long targetNs) {
            if (thread == null) {
                thread = Thread.currentThread();
            }
            parkUntil(targetNs);
        }

        /**
         * Sleeps with the {@link MonotonicSleeper} until the wall instant the clock's target maps
         * to, at most {@value #MAX_PARK_NS} ns at a time (an unpark cannot end this sleep, so a
         * stop is seen at the next wake-up). The world time is read before the wall time, so the
         * wall target is never before the world target and a sleep is not repeated for the few
         * nanoseconds between the two reads.
         */
        @Override
        public void sleep(long targetNs) {
            if (sleeper == null) {
                parkUntil(targetNs);
                return;
            }
            long remainingNs = targetNs == Long.MAX_VALUE ? Long.MAX_VALUE : targetNs - clock.nanos();
            if (remainingNs > 0) {
                long wallNs = Math.min(MAX_PARK_NS, Math.max(1, clock.toWallNanos(remainingNs)));
                sleeper.sleepUntil(System.nanoTime() + wallNs);
            }
        }

        @Override
        public void wake() {
            LockSupport.unpark(thread); // no effect while the thread is not bound yet
        }

        @Override
        public void done() {
            // Nothing to track.
        }
    }

    private void parkUntil(long targetNs) {
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
    public long zeroCycleSpacingNs() {
        return 0;
    }

    @Override
    public void close() {
        // Holds nothing.
    }
}
