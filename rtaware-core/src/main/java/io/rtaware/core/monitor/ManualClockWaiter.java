package io.rtaware.core.monitor;

import io.rtaware.core.time.ManualClock;
import java.util.concurrent.atomic.AtomicLongArray;
import java.util.concurrent.atomic.AtomicReferenceArray;
import java.util.concurrent.locks.LockSupport;

/**
 * Waits on a {@link ManualClock}: a thread parks until the clock is advanced (every advance
 * unparks every party), so the threaded executor, with its real threads, runs on stepped time.
 * A test can then step exactly as WPILib tests its {@code TimedRobot} on paused time: advance
 * to the next moment something is due ({@link #nextWakeNs()}), wait until every thread has
 * reacted and is waiting again ({@link #awaitIdle()}), repeat. Thread-safe.
 */
final class ManualClockWaiter implements ClockWaiter {

    /** Slot value of a party that is running (not waiting). */
    private static final long BUSY = Long.MIN_VALUE;
    /** Slot value of a party that will not wait again. */
    private static final long DONE = Long.MAX_VALUE;
    /** Idle step of zero-duration continuous cycles, as in the step executor. */
    private static final long ZERO_CYCLE_SPACING_NS = StepExecutor.DEFAULT_IDLE_STEP_NS;
    /** Guard against a test that waits forever for a thread that never parks (a bug). */
    private static final long IDLE_TIMEOUT_NS = 10_000_000_000L;

    private final ManualClock clock;
    private final AtomicReferenceArray<Thread> threads;
    /** Per party: the world time it waits for, {@link #BUSY} or {@link #DONE}. */
    private final AtomicLongArray waitingUntil;
    private final Runnable unsubscribe;

    /**
     * @param clock the clock the threads wait on
     * @param parties how many threads wait (tasks plus the watchdog)
     */
    ManualClockWaiter(ManualClock clock, int parties) {
        this.clock = clock;
        this.threads = new AtomicReferenceArray<>(parties);
        this.waitingUntil = new AtomicLongArray(parties);
        for (int i = 0; i < parties; i++) {
            waitingUntil.set(i, BUSY);
        }
        this.unsubscribe = clock.onAdvance((fromNs, toNs) -> {
            for (int i = 0; i < threads.length(); i++) {
                Thread t = threads.get(i);
                if (t != null) {
                    LockSupport.unpark(t);
                }
            }
        });
    }

    @Override
    public void register(int party, Thread thread) {
        threads.set(party, thread);
    }

    @Override
    public void park(int party, long targetNs) {
        if (clock.nanos() >= targetNs) {
            return;
        }
        // Announced before the re-check: an advance after the check unparks this thread, and an
        // unpark before the park makes the park return at once.
        waitingUntil.set(party, targetNs);
        if (clock.nanos() < targetNs) {
            LockSupport.park(this);
        }
        waitingUntil.set(party, BUSY);
    }

    @Override
    public void busy(int party) {
        waitingUntil.set(party, BUSY);
    }

    @Override
    public void done(int party) {
        waitingUntil.set(party, DONE);
    }

    @Override
    public long zeroCycleSpacingNs() {
        return ZERO_CYCLE_SPACING_NS;
    }

    @Override
    public void close() {
        unsubscribe.run();
    }

    /**
     * Waits until every party is parked for a time still ahead of the clock, or done: nothing
     * happens any more until the clock is advanced.
     *
     * @throws IllegalStateException if that does not happen within 10 s of wall time
     */
    void awaitIdle() {
        long giveUpNs = System.nanoTime() + IDLE_TIMEOUT_NS;
        while (!isIdle()) {
            if (System.nanoTime() - giveUpNs > 0) {
                throw new IllegalStateException("the executor's threads did not become idle at t=" + clock.nanos()
                        + " ns: " + waitingUntil);
            }
            Thread.yield();
        }
    }

    private boolean isIdle() {
        long now = clock.nanos();
        for (int i = 0; i < waitingUntil.length(); i++) {
            long until = waitingUntil.get(i);
            if (until == BUSY || (until != DONE && until <= now)) {
                return false;
            }
        }
        return true;
    }

    /** @return the earliest world time a party waits for ({@link Long#MAX_VALUE} if none waits) */
    long nextWakeNs() {
        long earliest = Long.MAX_VALUE;
        for (int i = 0; i < waitingUntil.length(); i++) {
            long until = waitingUntil.get(i);
            if (until != BUSY && until != DONE && until < earliest) {
                earliest = until;
            }
        }
        return earliest;
    }
}
