package io.rtaware.core.monitor;

import io.rtaware.core.time.ManualClock;

/**
 * Drives a monitor started with {@link Monitor#start()} on a {@link ManualClock}, or an agent
 * that idles with a {@link WorldClockIdleStrategy} on one: its real task threads (or pool
 * workers) and watchdog, or the agent's thread, wait on the manual clock, and this steps the clock from
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
        this(clock, monitor.executor() instanceof PooledExecutor pool ? pool.waiter()
                : ((ThreadedExecutor) monitor.executor()).waiter());
    }

    /**
     * @param agentIdle the idle strategy of an agent whose thread has been started, built on {@code clock}
     * @param clock its manual clock
     */
    public SteppedThreads(WorldClockIdleStrategy agentIdle, ManualClock clock) {
        this(clock, agentIdle.waiter());
    }

    private SteppedThreads(ManualClock clock, ClockWaiter waiter) {
        this.clock = clock;
        this.waiter = (ManualClockWaiter) waiter;
    }

    /**
     * Runs every release (every agent's work) before {@code endNs}; the clock stays at the last
     * moment something was due, and every cycle due until then has run when this returns.
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
