package io.rtaware.core.monitor;

/**
 * How the threads of an executor wait for world time, in the spirit of Agrona's
 * {@code IdleStrategy}: the executor loops "while the clock is before the target, park", and
 * this decides what a park is. Every waiting thread is a numbered party (task i is party i, the
 * watchdog the last), so a waiter that needs to know who is idle can tell.
 *
 * <p>Two kinds: {@link ParkingClockWaiter} parks for the wall time the clock says is left
 * (real and scaled clocks); {@link ManualClockWaiter} parks until the manual clock is advanced,
 * so the threaded executor runs on stepped time with exact results. Thread-safe.
 */
interface ClockWaiter {

    /**
     * @param party the calling thread's party number
     * @param thread that thread (before it first waits)
     */
    void register(int party, Thread thread);

    /**
     * Parks the calling thread for at most the time until the clock reaches {@code targetNs};
     * may return earlier (an unpark, an advance, a spurious wake-up): callers re-check the clock.
     *
     * @param party the caller's party number
     * @param targetNs world time
     */
    void park(int party, long targetNs);

    /**
     * Like {@link #park}, for a party that nobody {@link #wake wakes} (a task thread of the
     * threaded executor, which only waits for its next release): the waiter may then use a sleep
     * that an unpark cannot cut short and that costs the operating system less (see
     * {@link io.rtaware.core.time.MonotonicSleeper}). By default, a park.
     *
     * @param party the caller's party number
     * @param targetNs world time
     */
    default void sleep(int party, long targetNs) {
        park(party, targetNs);
    }

    /**
     * Wakes party {@code party} for another thread (new work, an earlier deadline): the request is
     * recorded before the thread is unparked, so a waiter that tracks who is idle never takes a
     * party that is about to wake for an idle one.
     *
     * @param party the party to wake
     * @param thread its thread
     */
    void wake(int party, Thread thread);

    /** Party {@code party} will not wait again (its thread is returning). */
    void done(int party);

    /** @return the spacing of zero-duration continuous cycles (see {@link TaskRuntime#begin}) */
    long zeroCycleSpacingNs();

    /** Releases what the waiter holds (a clock subscription); after the threads have returned. */
    void close();
}
