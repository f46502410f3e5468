package io.rtaware.core.monitor;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;

/**
 * Which of a periodic task's cycles is running, shared by the task's thread and the watchdog so
 * that each miss is reported exactly once: whoever claims a running cycle past its deadline
 * (the watchdog at the deadline, or the task's thread when the cycle returns) reports it; a cycle
 * that starts after its deadline is reported by the task's thread at its start.
 *
 * <p>One long, accessed through a {@link VarHandle} (not an {@code AtomicLong}: with thousands of
 * tasks each object a cycle touches is a cache miss of its own): odd {@code 2k+1} while cycle k
 * runs; even when none runs (a claim moves {@code 2k+1} to {@code 2k+2}). Thread-safe and
 * allocation-free.
 */
final class CycleToken {

    private static final VarHandle TOKEN;

    static {
        try {
            TOKEN = MethodHandles.lookup().findVarHandle(CycleToken.class, "token", long.class);
        } catch (ReflectiveOperationException e) {
            throw new ExceptionInInitializerError(e);
        }
    }

    /** Written through {@link #TOKEN} only: volatile stores and compare-and-sets. */
    private long token;

    /** Marks cycle {@code k} running (task thread). */
    void start(long k) {
        TOKEN.setVolatile(this, 2 * k + 1);
    }

    /**
     * Starts cycle {@code k} whose deadline had already passed when it started (task thread): its
     * miss is certain and the caller reports it now, so the cycle is never seen as running: the
     * watchdog has nothing to claim and {@link #finish} returns false.
     */
    void startAlreadyMissed(long k) {
        TOKEN.setVolatile(this, 2 * k + 2);
    }

    /**
     * Ends cycle {@code k} (task thread).
     *
     * @return true if the watchdog had not claimed it: a late end is then the caller's to report
     */
    boolean finish(long k) {
        return TOKEN.compareAndSet(this, 2 * k + 1, 2 * k + 2);
    }

    /** @return the index of the running cycle, or -1 if none runs */
    long running() {
        long t = (long) TOKEN.getVolatile(this);
        return (t & 1) == 1 ? (t - 1) >>> 1 : -1;
    }

    /**
     * Claims cycle {@code k} for the watchdog if it is still the running one.
     *
     * @return true if claimed: the caller reports its miss
     */
    boolean claim(long k) {
        return TOKEN.compareAndSet(this, 2 * k + 1, 2 * k + 2);
    }
}
