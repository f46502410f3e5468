package io.rtaware.core.agent;

import java.util.Objects;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;
import org.agrona.ErrorHandler;
import org.agrona.concurrent.Agent;
import org.agrona.concurrent.AgentRunner;
import org.agrona.concurrent.AgentTerminationException;
import org.agrona.concurrent.IdleStrategy;

/**
 * A background loop on a daemon thread of its own, named for the agent's
 * {@link Agent#roleName() role}, run by Agrona's {@link AgentRunner}: {@link Agent#onStart()},
 * then {@link Agent#doWork()} and {@link IdleStrategy#idle(int)} in turn until closed, then
 * {@link Agent#onClose()}, all on that thread (and then the idle strategy's {@code close()}, if it
 * is {@link AutoCloseable}: a {@link io.rtaware.core.monitor.WorldClockIdleStrategy} lets go of
 * its clock). Every throwable of the agent, {@link Error}s
 * included, goes to one {@link ErrorHandler} and is counted ({@link #errors()}), and so does a
 * thread that has not returned when {@link #close()} gives up waiting; the loop goes on
 * (an {@link org.agrona.concurrent.AgentTerminationException} ends it), and {@link Agent#onClose()}
 * runs when it ends, whatever was thrown before. (Agrona's runner rethrows an {@code Error} and
 * skips {@code onClose}; this class hands it to the handler itself, so that, for instance, a
 * recorder's writer still drains and finishes its file after an {@code OutOfMemoryError}.)
 *
 * <p>{@link #close()} may be called from any thread, more than once: it stops the loop, wakes the
 * thread if it is parked (an agent that waits with {@link LockSupport#parkNanos(long)}, in its work
 * or in an idle strategy such as Agrona's {@link org.agrona.concurrent.SleepingIdleStrategy}, ends
 * at once, not after its wait) and waits for it as its {@link CloseWait} says: by default
 * interrupting it every {@value #CLOSE_TIMEOUT_MS} ms while it has not returned (an agent blocked
 * in I/O is interrupted). Called from the agent's own thread it only stops the loop. Thread-safe.
 */
public final class AgentThread implements AutoCloseable {

    /** How long {@link #close()} waits for the thread before it interrupts it (and waits again), ms. */
    public static final int CLOSE_TIMEOUT_MS = 2_000;

    /** How {@link AgentThread#close()} waits for the agent's thread. */
    public enum CloseWait {
        /**
         * Waits {@value AgentThread#CLOSE_TIMEOUT_MS} ms, then interrupts the thread, again every
         * {@value AgentThread#CLOSE_TIMEOUT_MS} ms until it returns: for loops an interrupt may end
         * (blocked in a wait or in interruptible I/O).
         */
        INTERRUPT_AFTER_TIMEOUT,
        /**
         * Waits as long as the agent takes to close, never interrupting it: for an agent whose
         * {@link Agent#onClose()} finishes work that an interrupt would destroy (an interrupt closes
         * a {@link java.nio.channels.FileChannel} the thread writes). If the closing thread is
         * interrupted while it waits, {@link AgentThread#close()} returns at once with its interrupt
         * status set.
         */
        UNTIL_CLOSED
    }

    /** Thrown by the loop itself once {@link #close()} was called; not an error. */
    private static final AgentTerminationException STOP = new AgentTerminationException("closed");

    private final AgentRunner runner;
    private final Thread thread;
    private final AtomicLong errors = new AtomicLong();
    /** The error handler, counting. */
    private final ErrorHandler counting;
    private final CloseWait closeWait;
    private volatile boolean stopRequested;

    private AgentThread(Agent agent, IdleStrategy idle, ErrorHandler errorHandler, CloseWait closeWait) {
        Objects.requireNonNull(errorHandler, "errorHandler");
        this.closeWait = Objects.requireNonNull(closeWait, "closeWait");
        this.counting = error -> {
            if (error != STOP) {
                errors.incrementAndGet();
                errorHandler.onError(error);
            }
        };
        this.runner = new AgentRunner(idle, counting, null, new Agent() {
            @Override
            public void onStart() {
                try {
                    agent.onStart();
                } catch (Error e) {
                    counting.onError(e);
                }
            }

            @Override
            public int doWork() throws Exception {
                if (stopRequested) {
                    throw STOP;
                }
                try {
                    return agent.doWork();
                } catch (Error e) {
                    counting.onError(e); // not rethrown: the runner would end the thread without onClose
                    return 0;
                }
            }

            @Override
            public void onClose() {
                try {
                    agent.onClose();
                } finally {
                    closeIdle(idle);
                }
            }

            @Override
            public String roleName() {
                return agent.roleName();
            }
        });
        this.thread = new Thread(runner, agent.roleName());
        thread.setDaemon(true);
    }

    /** After the agent's close, on its thread: an idle strategy that holds something lets go of it. */
    private void closeIdle(IdleStrategy idle) {
        if (idle instanceof AutoCloseable closeable) {
            try {
                closeable.close();
            } catch (Exception e) {
                counting.onError(e);
            }
        }
    }

    /**
     * Starts an agent on a thread of its own.
     *
     * @param agent the loop's work; its role name names the thread
     * @param idle what to do after a duty cycle (e.g. Agrona's
     *     {@link org.agrona.concurrent.SleepingMillisIdleStrategy} for a loop that polls, a
     *     {@link io.rtaware.core.monitor.WorldClockIdleStrategy} for one whose work is due at
     *     moments of world time); one that is {@link AutoCloseable} is closed after the agent
     * @param errorHandler where every throwable of the agent goes, on the agent's thread (a
     *     thread stuck past close's wait: on the closing thread)
     * @return the running loop, closed with {@link CloseWait#INTERRUPT_AFTER_TIMEOUT}
     */
    public static AgentThread start(Agent agent, IdleStrategy idle, ErrorHandler errorHandler) {
        return start(agent, idle, errorHandler, CloseWait.INTERRUPT_AFTER_TIMEOUT);
    }

    /**
     * Starts an agent on a thread of its own.
     *
     * @param agent the loop's work; its role name names the thread
     * @param idle what to do after a duty cycle; one that is {@link AutoCloseable} is closed after the agent
     * @param errorHandler where every throwable of the agent goes, on the agent's thread (a
     *     thread stuck past close's wait: on the closing thread)
     * @param closeWait how {@link #close()} waits for the thread
     * @return the running loop
     */
    public static AgentThread start(Agent agent, IdleStrategy idle, ErrorHandler errorHandler, CloseWait closeWait) {
        AgentThread loop = new AgentThread(agent, idle, errorHandler, closeWait);
        loop.thread.start();
        return loop;
    }

    /** @return how many throwables the agent has thrown so far, and how often close found it stuck */
    public long errors() {
        return errors.get();
    }

    /** @return whether the loop has ended and its {@link Agent#onClose()} has run */
    public boolean isClosed() {
        return runner.isClosed();
    }

    /**
     * Stops the loop and waits until the agent has closed on its thread (see the class comment).
     * An interrupt the calling thread already had (how Ctrl-C stops {@code rtaware sim}) does not
     * cut the wait short: it is cleared while waiting and set again when close returns.
     */
    @Override
    public void close() {
        stopRequested = true;
        if (Thread.currentThread() == thread) {
            return;
        }
        LockSupport.unpark(thread);
        boolean interruptedBefore = Thread.interrupted();
        try {
            if (closeWait == CloseWait.UNTIL_CLOSED) {
                thread.join();
            } else {
                runner.close(CLOSE_TIMEOUT_MS, stuck -> counting.onError(new IllegalStateException(stuck.getName()
                        + " did not return within " + CLOSE_TIMEOUT_MS + " ms of close; interrupting it")));
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt(); // interrupted while waiting: returns at once
        } finally {
            if (interruptedBefore) {
                Thread.currentThread().interrupt();
            }
        }
    }
}
