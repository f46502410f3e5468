package io.rtaware.core.monitor;

import io.rtaware.core.time.ManualClock;
import java.util.Arrays;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicLongFieldUpdater;
import java.util.concurrent.locks.LockSupport;

/**
 * Waits on a {@link ManualClock}: a thread parks until the clock is advanced (every advance
 * wakes every party), so the threaded and pooled executors, with their real threads, run on
 * stepped time. A test can then step exactly as WPILib tests its {@code TimedRobot} on paused
 * time: wait until every thread is waiting for a time still ahead ({@link #awaitIdleNextWakeNs()}),
 * advance the clock to the earliest of those times, repeat.
 *
 * <p>Idle is decided on one consistent view. Per party it keeps the time it waits for, the
 * number of wake requests made for it (an advance of the clock, another thread's
 * {@link Party#wake}) and the number it had seen when it announced its wait: a party whose requests
 * outnumber what it has seen is about to wake, whatever its announced time says. Every change
 * of that state bumps one counter, and a view is taken only if the counter did not move while
 * it was read. A stale permit (an unpark of a thread that was running) only makes a thread wait
 * again for the same time, which changes nothing a view depends on. Thread-safe.
 */
final class ManualClockWaiter implements ClockWaiter {

    /** Slot value of a party that is running (not waiting). */
    private static final long BUSY = Long.MIN_VALUE;
    /** Slot value of a party that will not wait again; never a world time (those are not negative). */
    private static final long DONE = Long.MIN_VALUE + 1;
    /** What {@link #idleNextWakeNs()} says while some party is not idle. */
    static final long NOT_IDLE = Long.MIN_VALUE;
    /** Idle step of zero-duration continuous cycles, as in the step executor. */
    private static final long ZERO_CYCLE_SPACING_NS = StepExecutor.DEFAULT_IDLE_STEP_NS;
    /** Guard against a test that waits forever for a thread that never parks (a bug). */
    private static final long IDLE_TIMEOUT_NS = 10_000_000_000L;

    private final ManualClock clock;
    /**
     * The registered parties, in registration order, in the first {@link #partyCount} slots; the
     * array is replaced by one twice as long when full. Written before the count, so a reader
     * that reads the count first finds every party it counts.
     */
    private volatile ManualParty[] parties = new ManualParty[8];
    private volatile int partyCount;
    /** Bumped by every change of a party's state: a view read while it stood still is consistent. */
    private final AtomicLong changes = new AtomicLong();
    private final Runnable unsubscribe;

    /**
     * @param clock the clock the threads wait on
     */
    ManualClockWaiter(ManualClock clock) {
        this.clock = clock;
        this.unsubscribe = clock.onAdvance((fromNs, toNs) -> {
            int count = partyCount;
            ManualParty[] all = parties;
            for (int i = 0; i < count; i++) {
                all[i].wake();
            }
        });
    }

    @Override
    public synchronized Party register(Thread thread) {
        ManualParty party = new ManualParty(thread);
        int count = partyCount;
        if (count == parties.length) {
            parties = Arrays.copyOf(parties, 2 * count);
        }
        parties[count] = party;
        partyCount = count + 1;
        changes.incrementAndGet();
        return party;
    }

    private static final AtomicLongFieldUpdater<ManualParty> WAKE_REQUESTS =
            AtomicLongFieldUpdater.newUpdater(ManualParty.class, "wakeRequests");

    /** One thread waiting on the manual clock. */
    final class ManualParty implements Party {
        /**
         * Null until the first wait of a party registered without its thread; bound before the
         * wait is announced, so a wake requested after the announcement finds it.
         */
        private volatile Thread thread;
        /** The world time it waits for ({@link Long#MAX_VALUE}: until woken), {@link #BUSY} or {@link #DONE}. */
        private volatile long waitingUntil = BUSY;
        /** Wake requests made for it so far; incremented through {@link #WAKE_REQUESTS}. */
        private volatile long wakeRequests;
        /** The wake requests it had seen when it announced its current wait. */
        private volatile long wakesSeen;

        ManualParty(Thread thread) {
            this.thread = thread;
        }

        @Override
        public void park(long targetNs) {
            if (thread == null) {
                thread = Thread.currentThread();
            }
            if (clock.nanos() >= targetNs) {
                return;
            }
            // Announced before the re-check: a wake requested after the announcement is seen by
            // the re-check or unparks this thread, and an unpark before the park makes it return
            // at once.
            long seen = wakeRequests;
            wakesSeen = seen;
            waitingUntil = targetNs;
            changes.incrementAndGet();
            if (clock.nanos() < targetNs && wakeRequests == seen) {
                LockSupport.park(ManualClockWaiter.this);
            }
            waitingUntil = BUSY;
            changes.incrementAndGet();
        }

        @Override
        public void wake() {
            requestWake();
            LockSupport.unpark(thread); // unbound: its first wait re-reads the clock after announcing
        }

        /** The first half of {@link #wake}: the request is recorded, the thread not yet unparked. */
        void requestWake() {
            WAKE_REQUESTS.incrementAndGet(this);
            changes.incrementAndGet();
        }

        @Override
        public void done() {
            waitingUntil = DONE;
            changes.incrementAndGet();
        }

        @Override
        public String toString() {
            Thread bound = thread;
            return (bound == null ? "(no thread yet)" : bound.getName()) + ": waiting until " + waitingUntil + ", wake requests " + wakeRequests
                    + ", seen " + wakesSeen;
        }
    }

    @Override
    public long zeroCycleSpacingNs() {
        return ZERO_CYCLE_SPACING_NS;
    }

    @Override
    public void close() {
        unsubscribe.run();
    }

    /**
     * Waits until every party waits for a time still ahead of the clock with no wake pending, or
     * is done: nothing happens any more until the clock is advanced.
     *
     * @return the earliest world time a party waits for ({@link Long#MAX_VALUE} if none waits for a time)
     * @throws IllegalStateException if that does not happen within 10 s of wall time
     */
    long awaitIdleNextWakeNs() {
        long giveUpNs = System.nanoTime() + IDLE_TIMEOUT_NS;
        while (true) {
            long next = idleNextWakeNs();
            if (next != NOT_IDLE) {
                return next;
            }
            if (System.nanoTime() - giveUpNs > 0) {
                throw new IllegalStateException("the executor's threads did not become idle at t=" + clock.nanos()
                        + " ns: " + Arrays.toString(Arrays.copyOf(parties, partyCount)));
            }
            Thread.yield();
        }
    }

    /**
     * One look, without waiting.
     *
     * @return the earliest time a party waits for, if all are idle in one consistent view; else
     *     {@link #NOT_IDLE}
     */
    long idleNextWakeNs() {
        long before = changes.get();
        long now = clock.nanos();
        long earliest = Long.MAX_VALUE;
        int count = partyCount;
        ManualParty[] all = parties;
        for (int i = 0; i < count; i++) {
            ManualParty party = all[i];
            long until = party.waitingUntil;
            if (until == DONE) {
                continue;
            }
            if (until == BUSY || until <= now || party.wakeRequests != party.wakesSeen) {
                return NOT_IDLE;
            }
            earliest = Math.min(earliest, until);
        }
        return changes.get() == before && clock.nanos() == now ? earliest : NOT_IDLE;
    }
}
