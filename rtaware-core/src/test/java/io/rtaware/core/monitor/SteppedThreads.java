package io.rtaware.core.monitor;

import io.rtaware.core.time.ManualClock;

/**
 * Drives a monitor started with {@link Monitor#start()} on a {@link ManualClock}: its real task
 * threads (or pool workers) and watchdog wait on the manual clock, and this steps the clock from
 * one moment something is due to the next, waiting each time until every thread has reacted and
 * waits again (as WPILib steps a TimedRobot on paused time). Exact, no sleeps. In core's test-jar
 * for every module's tests (in this package: it reaches the executor's clock waiter).
 */
public final class SteppedThreads {

    private final ManualClock clock;
    private final ManualClockWaiter waiter;

    /**
     * @param monitor a monitor built on {@code clock}, started with {@link Monitor#start()}
     * @param clock its manual clock
     */
    public SteppedThreads(Monitor monitor, ManualClock clock) {
        this.clock = clock;
        Executor executor = monitor.executor();
        this.waiter = (ManualClockWaiter) (executor instanceof PooledExecutor pool
                ? pool.waiter() : ((ThreadedExecutor) executor).waiter());
    }

    /**
     * Runs every release before {@code endNs}; the clock stays at the last moment something was
     * due, and every cycle due until then has run when this returns.
     *
     * @param endNs world time, ns
     */
    public void runUntil(long endNs) {
        while (true) {
            long next = waiter.awaitIdleNextWakeNs();
            if (next >= endNs) {
                return;
            }
            clock.advanceTo(next);
        }
    }
}
