package io.rtaware.core.data;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.util.concurrent.locks.LockSupport;
import java.util.concurrent.locks.StampedLock;

/**
 * One key's state in the store: the newest value, its generation counter and commit time, and
 * the feed statistics of its commits.
 *
 * <p>Thread-safe: any number of consumers copy out under the shared read lock while the single
 * producer commits under the exclusive write lock (the paper's locking scheme, with
 * {@link StampedLock}, whose read lock keeps no per-thread hold count). Neither path allocates:
 * the locks are taken with {@code tryWriteLock}/{@code tryReadLock} and a short back-off, never
 * by joining StampedLock's wait queue, whose nodes are allocated on contention (the Epsilon guard
 * caught a {@code StampedLock$WriterNode} from a commit that met a reader). A copy in or out takes
 * well under a microsecond, so a waiter spins briefly, then yields, then parks for
 * {@value #BACK_OFF_PARK_NS} ns at a time.
 *
 * @param <T> the value type
 */
public final class StateVariable<T extends StateValue<T>> {

    /** Busy-wait rounds before a waiter starts yielding the processor. */
    private static final int SPINS = 16;
    /** Rounds (spinning included) before a waiter starts parking. */
    private static final int YIELDS = 1024;
    /** How long a waiter parks per round once it parks, ns. */
    static final long BACK_OFF_PARK_NS = 10_000L;

    private final Key<T> key;
    private final T value;
    private final StampedLock lock = new StampedLock();
    /** Set by the producer while it waits for readers to leave (one producer per key). */
    private volatile boolean writerWaiting;

    /**
     * Read with volatile reads; written, under the write lock, with an ordered store: the write
     * lock's release right after it is a volatile store, which makes both visible in order, so a
     * volatile store here would only add a second full fence to every commit.
     */
    private volatile long generation;
    private static final VarHandle GENERATION;

    static {
        try {
            GENERATION = MethodHandles.lookup().findVarHandle(StateVariable.class, "generation", long.class);
        } catch (ReflectiveOperationException e) {
            throw new ExceptionInInitializerError(e);
        }
    }
    private long commitTimeNs;
    private long firstCommitNs;
    private long minIntervalNs = Long.MAX_VALUE;
    private long maxIntervalNs;

    /**
     * @param key the variable's key; its factory allocates the stored buffer now
     */
    public StateVariable(Key<T> key) {
        this.key = key;
        this.value = key.newBuffer();
    }

    /** @return the key */
    public Key<T> key() {
        return key;
    }

    /**
     * Copies the producer's buffer in, under the write lock, and counts the commit.
     *
     * @param source the producer's buffer
     * @param nowNs world time of the commit
     */
    public void commit(T source, long nowNs) {
        long stamp = writeLock();
        try {
            value.copyFrom(source);
            long gen = generation;
            if (gen == 0) {
                firstCommitNs = nowNs;
            } else {
                long interval = nowNs - commitTimeNs;
                if (interval < minIntervalNs) {
                    minIntervalNs = interval;
                }
                if (interval > maxIntervalNs) {
                    maxIntervalNs = interval;
                }
            }
            commitTimeNs = nowNs;
            GENERATION.setRelease(this, gen + 1);
        } finally {
            lock.unlockWrite(stamp);
        }
    }

    /**
     * Copies the newest value into a consumer's buffer if it is newer than the generation the
     * consumer already holds. Called at the start of the consumer's cycle.
     *
     * @param target the consumer's buffer
     * @param heldGeneration the generation the consumer's buffer holds (0 if none)
     * @param cursor receives the generation and commit time of the value now in {@code target}
     */
    public void copyTo(T target, long heldGeneration, ReadCursor cursor) {
        if (generation == heldGeneration) {
            // Volatile read: nothing newer is committed, the consumer's copy is current.
            cursor.set(heldGeneration, cursor.commitTimeNs());
            return;
        }
        long stamp = readLock();
        try {
            target.copyFrom(value);
            cursor.set(generation, commitTimeNs);
        } finally {
            lock.unlockRead(stamp);
        }
    }

    /** @return how many commits were made */
    public long generation() {
        return generation;
    }

    /** @return a consistent snapshot of the feed statistics */
    public FeedStats feedStats() {
        long stamp = readLock();
        try {
            long gen = generation;
            return new FeedStats(gen, gen == 0 ? 0 : firstCommitNs, gen == 0 ? 0 : commitTimeNs,
                    gen < 2 ? 0 : minIntervalNs, gen < 2 ? 0 : maxIntervalNs);
        } finally {
            lock.unlockRead(stamp);
        }
    }

    private long writeLock() {
        long stamp = lock.tryWriteLock();
        if (stamp != 0L) {
            return stamp;
        }
        // Readers hold the lock: announce the commit so that no new reader enters meanwhile,
        // or a steady stream of readers would keep the producer out.
        writerWaiting = true;
        for (int round = 0; stamp == 0L; round++) {
            backOff(round);
            stamp = lock.tryWriteLock();
        }
        writerWaiting = false;
        return stamp;
    }

    private long readLock() {
        for (int round = 0; ; round++) {
            if (!writerWaiting) {
                long stamp = lock.tryReadLock();
                if (stamp != 0L) {
                    return stamp;
                }
            }
            backOff(round);
        }
    }

    private static void backOff(int round) {
        if (round < SPINS) {
            Thread.onSpinWait();
        } else if (round < YIELDS) {
            Thread.yield();
        } else {
            LockSupport.parkNanos(BACK_OFF_PARK_NS);
        }
    }

    /**
     * Mutable holder of what a copy-out found; one per consumer input, reused every cycle.
     * Not thread-safe.
     */
    public static final class ReadCursor {
        private long generation;
        private long commitTimeNs;

        void set(long gen, long commitNs) {
            this.generation = gen;
            this.commitTimeNs = commitNs;
        }

        /** @return the generation copied */
        public long generation() {
            return generation;
        }

        /** @return the commit time of the generation copied */
        public long commitTimeNs() {
            return commitTimeNs;
        }
    }
}
