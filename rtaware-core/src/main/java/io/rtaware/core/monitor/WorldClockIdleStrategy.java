package io.rtaware.core.monitor;

import io.rtaware.core.time.Clock;
import io.rtaware.core.time.ManualClock;
import org.agrona.concurrent.IdleStrategy;

/**
 * The idle strategy of an agent whose work is due at moments of world time (a referee that
 * samples every 100 ms, a simulator that steps its world): its {@code doWork} says when it next
 * has work ({@link #wakeAt(long)}) and returns 0, and the idle waits until the clock reaches
 * that time through the same clock waiter the monitor's executors wait with. On a real or scaled
 * clock it parks for the wall time left ({@link Clock#toWallNanos(long)}); on a
 * {@link ManualClock} it parks until the clock is advanced, so an agent runs on stepped time with
 * exact results, as the executors' threads do (the tests' {@code SteppedThreads} steps it).
 * A park may end early (an advance short of the time, a spurious wake-up, the
 * {@link io.rtaware.core.agent.AgentThread}'s close, which unparks the thread): the agent's next
 * {@code doWork} reads the clock again.
 *
 * <p>One per agent, built before its thread starts and given to
 * {@link io.rtaware.core.agent.AgentThread#start}, which closes it when the agent has closed.
 * {@link #wakeAt(long)} and the idle methods are called by the agent's thread only, {@link #close()}
 * once that thread waits no more. Allocation-free after construction.
 */
public final class WorldClockIdleStrategy implements IdleStrategy, AutoCloseable {

    private final ClockWaiter waiter;
    /** Registered before the agent's thread exists; bound to the first thread that idles. */
    private final ClockWaiter.Party party;
    /** World time of the agent's next work; {@link Long#MAX_VALUE} until it names one. */
    private long wakeAtNs = Long.MAX_VALUE;

    /**
     * @param clock the world clock the agent's work is due on (a {@link ManualClock} in tests)
     */
    public WorldClockIdleStrategy(Clock clock) {
        this.waiter = ClockWaiter.forClock(clock, null);
        this.party = waiter.register(null);
    }

    /**
     * Says when the agent has work next; the next idle without work waits until then. Called by
     * the agent's {@code doWork} before it returns 0.
     *
     * @param worldNs world time of the next work, ns ({@link Long#MAX_VALUE}: none foreseen, wait
     *     until woken or, on a real clock, look again every 100 ms)
     */
    public void wakeAt(long worldNs) {
        wakeAtNs = worldNs;
    }

    /**
     * After a duty cycle: returns at once if the agent did work, else waits as {@link #idle()}.
     *
     * @param workCount what the agent's {@code doWork} returned
     */
    @Override
    public void idle(int workCount) {
        if (workCount <= 0) {
            idle();
        }
    }

    /** Waits until the clock reaches the time of {@link #wakeAt(long)}, or less (see the class comment). */
    @Override
    public void idle() {
        party.park(wakeAtNs);
    }

    /** Nothing to reset: the wait follows the time the agent names. */
    @Override
    public void reset() {
        // Holds no back-off state.
    }

    /** @return {@code "world-clock"} */
    @Override
    public String alias() {
        return "world-clock";
    }

    /** The agent's thread waits no more: its party is done and the waiter lets go of the clock. */
    @Override
    public void close() {
        party.done();
        waiter.close();
    }

    /** @return the waiter it waits with (tests on a manual clock step through it) */
    ClockWaiter waiter() {
        return waiter;
    }
}
