package io.rtaware.core.monitor;

import io.rtaware.core.time.Clock;
import io.rtaware.core.time.ManualClock;
import io.rtaware.core.time.MonotonicSleeper;

/**
 * How the threads of an executor wait for world time, in the spirit of Agrona's
 * {@code IdleStrategy}: the executor loops "while the clock is before the target, park", and
 * this decides what a park is. Every thread that waits registers once and gets its
 * {@link Party}, the handle it waits with and other threads wake it with, so a waiter that needs
 * to know who is idle can tell.
 *
 * <p>Two kinds: {@link ParkingClockWaiter} parks for the wall time the clock says is left
 * (real and scaled clocks); {@link ManualClockWaiter} parks until the manual clock is advanced,
 * so the threaded executor runs on stepped time with exact results. The executors and the
 * agents that wait for world time ({@link WorldClockIdleStrategy}) wait through it. Thread-safe.
 */
interface ClockWaiter {

    /**
     * The waiter for a clock: one that parks until a {@link ManualClock} is advanced, else one
     * that parks for the wall time left.
     *
     * @param clock the world clock
     * @param sleeper what a real clock's {@link Party#sleep} uses, or null to park there too
     * @return a new waiter on that clock
     */
    static ClockWaiter forClock(Clock clock, MonotonicSleeper sleeper) {
        return clock instanceof ManualClock manual ? new ManualClockWaiter(manual) : new ParkingClockWaiter(clock, sleeper);
    }

    /**
     * Registers a thread that will wait; before it first waits and before the executor's start
     * returns.
     *
     * @param thread the thread (not yet started, or the calling one), or null for a party whose
     *     thread is the first one that waits with it (an agent's, registered before its thread exists)
     * @return its party
     */
    Party register(Thread thread);

    /** @return the spacing of zero-duration continuous cycles (see {@link TaskRuntime#begin}) */
    long zeroCycleSpacingNs();

    /** Releases what the waiter holds (a clock subscription); after the threads have returned. */
    void close();

    /**
     * One registered thread. {@link #park}, {@link #sleep} and {@link #done} are called by that
     * thread only; {@link #wake} by any thread.
     */
    interface Party {

        /**
         * Parks the calling thread for at most the time until the clock reaches {@code targetNs};
         * may return earlier (an unpark, an advance, a spurious wake-up): callers re-check the clock.
         *
         * @param targetNs world time
         */
        void park(long targetNs);

        /**
         * Like {@link #park}, for a party that nobody {@link #wake wakes} (a task thread of the
         * threaded executor, which only waits for its next release): the waiter may then use a
         * sleep that an unpark cannot cut short and that costs the operating system less (see
         * {@link io.rtaware.core.time.MonotonicSleeper}). By default, a park.
         *
         * @param targetNs world time
         */
        default void sleep(long targetNs) {
            park(targetNs);
        }

        /**
         * Wakes this party's thread for another thread (new work, an earlier deadline): the
         * request is recorded before the thread is unparked, so a waiter that tracks who is idle
         * never takes a party that is about to wake for an idle one.
         */
        void wake();

        /** This party will not wait again (its thread is returning). */
        void done();
    }
}
