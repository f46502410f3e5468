package io.rtaware.core.agent;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.agrona.concurrent.Agent;
import java.util.concurrent.atomic.AtomicBoolean;
import org.agrona.concurrent.NoOpIdleStrategy;
import org.agrona.concurrent.SleepingIdleStrategy;
import org.agrona.concurrent.SleepingMillisIdleStrategy;
import org.junit.jupiter.api.Test;

/** The contract of a background loop, on real threads, ordered by latches (no timing). */
class AgentThreadTest {

    /**
     * Records on which thread each step ran; throws an {@link Error} in its second duty cycle (as
     * an {@link OutOfMemoryError} would be) and an exception in its third.
     */
    private static final class Recorder implements Agent {
        final List<String> steps = new CopyOnWriteArrayList<>();
        final CountDownLatch fiveCycles = new CountDownLatch(5);
        int cycles;

        @Override
        public void onStart() {
            steps.add("start on " + Thread.currentThread().getName());
        }

        @Override
        public int doWork() {
            cycles++;
            fiveCycles.countDown();
            if (cycles == 2) {
                throw new OutOfMemoryError("cycle 2");
            }
            if (cycles == 3) {
                throw new IllegalStateException("cycle 3");
            }
            return 0;
        }

        @Override
        public void onClose() {
            steps.add("close on " + Thread.currentThread().getName());
        }

        @Override
        public String roleName() {
            return "test-agent";
        }
    }

    /** An agent whose onClose does work that an interrupt would cut short; says whether one did. */
    private static final class SlowClosingAgent implements Agent {
        /** What onClose does. */
        interface Closing {
            void run() throws InterruptedException;
        }

        final CountDownLatch started = new CountDownLatch(1);
        final AtomicBoolean interrupted = new AtomicBoolean();
        private final String role;
        private final Closing closing;

        SlowClosingAgent(String role, Closing closing) {
            this.role = role;
            this.closing = closing;
        }

        @Override
        public int doWork() {
            started.countDown();
            return 0;
        }

        @Override
        public void onClose() {
            try {
                closing.run();
            } catch (InterruptedException e) {
                interrupted.set(true);
            }
        }

        @Override
        public String roleName() {
            return role;
        }
    }

    @Test
    void errorsAndExceptionsGoToOneHandlerAndACounterAndTheLoopGoesOnUntilClosedOnItsOwnThread() throws Exception {
        Recorder agent = new Recorder();
        List<String> handled = new CopyOnWriteArrayList<>();
        AgentThread loop = AgentThread.start(agent, NoOpIdleStrategy.INSTANCE, e -> handled.add(e.getMessage()));
        assertTrue(agent.fiveCycles.await(10, TimeUnit.SECONDS), "the loop went on after the Error and the exception");
        loop.close();

        assertTrue(loop.isClosed(), "close returns once the agent has closed");
        assertEquals(List.of("cycle 2", "cycle 3"), handled, "every error to the one handler, in order");
        assertEquals(2, loop.errors(), "and counted");
        assertEquals(List.of("start on test-agent", "close on test-agent"), agent.steps,
                "onStart and onClose on the agent's own thread, named for its role (onClose after an Error too)");
        loop.close(); // a second close does nothing
    }

    @Test
    void closeFromTheAgentsOwnThreadStopsTheLoopWithoutAnError() throws Exception {
        CountDownLatch closed = new CountDownLatch(1);
        AgentThread[] self = new AgentThread[1];
        CountDownLatch started = new CountDownLatch(1);
        Agent agent = new Agent() {
            @Override
            public int doWork() throws InterruptedException {
                started.await();
                self[0].close();
                return 0;
            }

            @Override
            public void onClose() {
                closed.countDown();
            }

            @Override
            public String roleName() {
                return "self-closing";
            }
        };
        self[0] = AgentThread.start(agent, new SleepingMillisIdleStrategy(1), e -> { });
        started.countDown();
        assertTrue(closed.await(10, TimeUnit.SECONDS), "the loop ended and closed the agent");
        self[0].close();
        assertEquals(0, self[0].errors(), "stopping is not an error");
    }

    @Test
    void anAgentBlockedInItsWorkIsInterruptedByCloseAfterTheTimeoutAndStops() throws Exception {
        CountDownLatch blocked = new CountDownLatch(1);
        Throwable[] seen = new Throwable[1];
        Agent agent = new Agent() {
            @Override
            public int doWork() throws InterruptedException {
                blocked.countDown();
                new CountDownLatch(1).await(); // blocks until interrupted
                return 0;
            }

            @Override
            public String roleName() {
                return "blocked";
            }
        };
        AgentThread loop = AgentThread.start(agent, NoOpIdleStrategy.INSTANCE, e -> seen[0] = e);
        assertTrue(blocked.await(10, TimeUnit.SECONDS));
        loop.close();
        assertTrue(loop.isClosed(), "close waited for the agent, interrupted after the timeout");
        // Issue 38, one loop contract: the stuck thread goes to the handler and the count (it was
        // printed to stderr beside them); the interrupt that then stops the loop is not an error.
        assertEquals("blocked did not return within " + AgentThread.CLOSE_TIMEOUT_MS + " ms of close; interrupting it",
                seen[0].getMessage());
        assertEquals(IllegalStateException.class, seen[0].getClass());
        assertEquals(1, loop.errors());
    }

    @Test
    void closeWakesAnAgentParkedInItsIdleStrategyInsteadOfInterruptingItAfterTheTimeout() throws Exception {
        CountDownLatch worked = new CountDownLatch(1);
        AtomicBoolean interruptedAtClose = new AtomicBoolean(true);
        Agent agent = new Agent() {
            @Override
            public int doWork() {
                worked.countDown();
                return 0;
            }

            @Override
            public void onClose() {
                interruptedAtClose.set(Thread.currentThread().isInterrupted());
            }

            @Override
            public String roleName() {
                return "parked";
            }
        };
        // Idles for an hour per duty cycle: only close's wake-up (or, without it, the interrupt after the timeout) ends it.
        AgentThread loop = AgentThread.start(agent, new SleepingIdleStrategy(TimeUnit.HOURS.toNanos(1)), e -> { });
        assertTrue(worked.await(10, TimeUnit.SECONDS));
        loop.close();
        assertTrue(loop.isClosed(), "close returns once the agent has closed");
        assertFalse(interruptedAtClose.get(), "woken by close, not interrupted after " + AgentThread.CLOSE_TIMEOUT_MS + " ms");
        assertEquals(0, loop.errors());
    }

    @Test
    void closeUntilClosedWaitsForALongOnCloseAndNeverInterruptsIt() throws Exception {
        List<String> steps = new CopyOnWriteArrayList<>();
        SlowClosingAgent agent = new SlowClosingAgent("finishing", () -> {
            // longer than the timeout after which the default close interrupts
            Thread.sleep(AgentThread.CLOSE_TIMEOUT_MS + 1_000);
            steps.add("finished its work");
        });
        AgentThread loop = AgentThread.start(agent, new SleepingIdleStrategy(TimeUnit.MILLISECONDS.toNanos(1)),
                e -> { }, AgentThread.CloseWait.UNTIL_CLOSED);
        assertTrue(agent.started.await(10, TimeUnit.SECONDS));
        loop.close();
        assertTrue(loop.isClosed(), "close returned only once onClose had returned");
        assertEquals(List.of("finished its work"), steps, "onClose ran to its end");
        assertFalse(agent.interrupted.get(), "never interrupted");
    }

    /**
     * How {@code sim} and {@code run} stop: Ctrl-C interrupts the main thread, which then closes
     * its loops. A pending interrupt must not cut the wait short (nor be passed on to the agent);
     * it is there again when close returns.
     */
    @Test
    void closeFromAnInterruptedThreadStillWaitsForOnCloseAndKeepsTheInterrupt() throws Exception {
        for (AgentThread.CloseWait wait : AgentThread.CloseWait.values()) {
            CountDownLatch mayFinish = new CountDownLatch(1);
            SlowClosingAgent agent = new SlowClosingAgent("closing-" + wait, mayFinish::await);
            AgentThread loop = AgentThread.start(agent, new SleepingIdleStrategy(TimeUnit.MILLISECONDS.toNanos(1)),
                    e -> { }, wait);
            assertTrue(agent.started.await(10, TimeUnit.SECONDS));
            Thread closer = new Thread(() -> {
                Thread.currentThread().interrupt();
                loop.close();
                if (!Thread.interrupted()) {
                    throw new AssertionError("close lost the caller's interrupt");
                }
            }, "interrupted-closer");
            List<Throwable> closerFailures = new CopyOnWriteArrayList<>();
            closer.setUncaughtExceptionHandler((t, e) -> closerFailures.add(e));
            closer.start();
            Thread.State state;
            while ((state = closer.getState()) == Thread.State.NEW || state == Thread.State.RUNNABLE) {
                Thread.onSpinWait(); // until close waits (for the agent) or has returned
            }
            assertFalse(state == Thread.State.TERMINATED, wait + ": close returned while onClose was still running");
            assertFalse(loop.isClosed(), wait + ": onClose is still waiting");
            mayFinish.countDown();
            closer.join();
            assertEquals(List.of(), closerFailures, wait.toString());
            assertTrue(loop.isClosed(), wait + ": close returned only once onClose had returned");
            assertFalse(agent.interrupted.get(), wait + ": the caller's interrupt was not passed to the agent");
        }
    }
}
