package io.rtaware.core.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.agent.AgentThread;
import io.rtaware.core.time.ManualClock;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.agrona.concurrent.Agent;
import org.junit.jupiter.api.Test;

/**
 * An agent that names the world time of its next work, on a real {@link AgentThread} that idles
 * with a {@link WorldClockIdleStrategy} on a manual clock, stepped exactly by {@link SteppedThreads}
 * (no sleeps, no timing).
 */
class WorldClockIdleStrategyTest {

    private static final long MS = 1_000_000L;

    /** Works at each due time and says when the next is due; records the world time of each work. */
    private static final class DueAgent implements Agent {
        final List<Long> workedAtNs = new CopyOnWriteArrayList<>();
        private final ManualClock clock;
        private final WorldClockIdleStrategy idle;
        private final long[] dueNs;
        private int next;

        DueAgent(ManualClock clock, WorldClockIdleStrategy idle, long... dueNs) {
            this.clock = clock;
            this.idle = idle;
            this.dueNs = dueNs;
        }

        @Override
        public int doWork() {
            long nowNs = clock.nanos();
            if (next == dueNs.length) {
                idle.wakeAt(Long.MAX_VALUE);
                return 0;
            }
            if (nowNs < dueNs[next]) {
                idle.wakeAt(dueNs[next]);
                return 0;
            }
            workedAtNs.add(nowNs);
            next++;
            return 1;
        }

        @Override
        public String roleName() {
            return "test-world-clock-agent";
        }
    }

    @Test
    void anAgentThatNeedsAWorldTimeDoesNoWorkBeforeItAndWorksWhenTheClockReachesIt() {
        ManualClock clock = new ManualClock(0);
        WorldClockIdleStrategy idle = new WorldClockIdleStrategy(clock);
        DueAgent agent = new DueAgent(clock, idle, 250 * MS);
        AgentThread loop = AgentThread.start(agent, idle, error -> { });
        SteppedThreads stepped = new SteppedThreads(idle, clock);
        try {
            stepped.runUntil(250 * MS);
            assertEquals(List.of(), agent.workedAtNs, "nothing is due before 250 ms");
            assertEquals(0, clock.nanos(), "and the clock was not moved: the agent waits for 250 ms");

            stepped.runUntil(250 * MS + 1);
            assertEquals(List.of(250 * MS), agent.workedAtNs, "the work ran once, when the clock reached 250 ms");
        } finally {
            loop.close();
        }
    }

    @Test
    void aPeriodicAgentWorksAtEveryDueTimeExactlyOnce() {
        ManualClock clock = new ManualClock(0);
        WorldClockIdleStrategy idle = new WorldClockIdleStrategy(clock);
        DueAgent agent = new DueAgent(clock, idle, 0, 100 * MS, 200 * MS, 300 * MS, 400 * MS);
        AgentThread loop = AgentThread.start(agent, idle, error -> { });
        try {
            new SteppedThreads(idle, clock).runUntil(350 * MS);
        } finally {
            loop.close();
        }
        assertEquals(List.of(0L, 100 * MS, 200 * MS, 300 * MS), agent.workedAtNs);
        assertEquals(300 * MS, clock.nanos(), "the clock went from one due time to the next, no further");
    }

    @Test
    void closingTheAgentWakesItsWaitAndEndsItsPartyInTheWaiter() {
        ManualClock clock = new ManualClock(0);
        WorldClockIdleStrategy idle = new WorldClockIdleStrategy(clock);
        DueAgent agent = new DueAgent(clock, idle); // nothing ever due: waits until woken
        AgentThread loop = AgentThread.start(agent, idle, error -> { });
        ManualClockWaiter waiter = (ManualClockWaiter) idle.waiter();
        assertEquals(Long.MAX_VALUE, waiter.awaitIdleNextWakeNs(), "the agent waits with no time named");

        loop.close();

        assertTrue(loop.isClosed(), "close woke the parked agent, which closed");
        assertEquals(Long.MAX_VALUE, waiter.idleNextWakeNs(),
                "the agent's party is done: a stepper no longer waits for it");
        assertEquals(0, loop.errors());
    }
}
