package io.rtaware.core.agent;

import java.util.Objects;
import java.util.concurrent.atomic.AtomicLong;
import org.agrona.ErrorHandler;
import org.agrona.concurrent.Agent;
import org.agrona.concurrent.AgentRunner;
import org.agrona.concurrent.AgentTerminationException;
import org.agrona.concurrent.IdleStrategy;

/**
 * A background loop on a daemon thread of its own, named for the agent's
 * {@link Agent#roleName() role}, run by Agrona's {@link AgentRunner}: {@link Agent#onStart()},
 * then {@link Agent#doWork()} and {@link IdleStrategy#idle(int)} in turn until closed, then
 * {@link Agent#onClose()}, all on that thread. Every throwable of the agent goes to one
 * {@link ErrorHandler} and is counted ({@link #errors()}); the loop goes on (an
 * {@link org.agrona.concurrent.AgentTerminationException} ends it).
 *
 * <p>{@link #close()} may be called from any thread, more than once: it stops the loop and waits
 * for the thread, interrupting it every {@value #CLOSE_TIMEOUT_MS} ms while it has not returned
 * (an agent blocked in I/O is interrupted). Called from the agent's own thread it only stops the
 * loop. Thread-safe.
 */
public final class AgentThread implements AutoCloseable {

    /** How long {@link #close()} waits for the thread before it interrupts it (and waits again), ms. */
    public static final int CLOSE_TIMEOUT_MS = 2_000;

    /** Thrown by the loop itself when {@link #close()} was called on the agent's thread; not an error. */
    private static final AgentTerminationException STOP = new AgentTerminationException("closed from its own thread");

    private final AgentRunner runner;
    private final Thread thread;
    private final AtomicLong errors = new AtomicLong();
    private volatile boolean stopRequested;

    private AgentThread(Agent agent, IdleStrategy idle, ErrorHandler errorHandler) {
        Objects.requireNonNull(errorHandler, "errorHandler");
        ErrorHandler counting = error -> {
            if (error != STOP) {
                errors.incrementAndGet();
                errorHandler.onError(error);
            }
        };
        this.runner = new AgentRunner(idle, counting, null, new Agent() {
            @Override
            public void onStart() {
                agent.onStart();
            }

            @Override
            public int doWork() throws Exception {
                if (stopRequested) {
                    throw STOP;
                }
                return agent.doWork();
            }

            @Override
            public void onClose() {
                agent.onClose();
            }

            @Override
            public String roleName() {
                return agent.roleName();
            }
        });
        this.thread = new Thread(runner, agent.roleName());
        thread.setDaemon(true);
    }

    /**
     * Starts an agent on a thread of its own.
     *
     * @param agent the loop's work; its role name names the thread
     * @param idle what to do after a duty cycle (e.g. Agrona's
     *     {@link org.agrona.concurrent.SleepingMillisIdleStrategy} for a loop that polls)
     * @param errorHandler where every throwable of the agent goes, on the agent's thread
     * @return the running loop
     */
    public static AgentThread start(Agent agent, IdleStrategy idle, ErrorHandler errorHandler) {
        AgentThread loop = new AgentThread(agent, idle, errorHandler);
        loop.thread.start();
        return loop;
    }

    /** @return how many throwables the agent has thrown so far */
    public long errors() {
        return errors.get();
    }

    /** @return whether the loop has ended and its {@link Agent#onClose()} has run */
    public boolean isClosed() {
        return runner.isClosed();
    }

    /** Stops the loop and waits until the agent has closed on its thread (see the class comment). */
    @Override
    public void close() {
        if (Thread.currentThread() == thread) {
            stopRequested = true;
            return;
        }
        runner.close(CLOSE_TIMEOUT_MS, stuck -> System.err.println("rtaware: " + stuck.getName()
                + " did not return within " + CLOSE_TIMEOUT_MS + " ms of close; interrupting it"));
    }
}
