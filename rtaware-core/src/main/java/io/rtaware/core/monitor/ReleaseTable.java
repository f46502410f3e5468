package io.rtaware.core.monitor;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;

/**
 * The release bookkeeping of every task of one monitor in one dense array: per task, its release
 * grid, its next release and its deadline token, eight longs side by side (64 bytes, a cache
 * line's worth), at {@code task * LONGS_PER_TASK}. {@link TaskRuntime} keeps the rules; this
 * table keeps the numbers they work on.
 *
 * <p>Why one array and not fields of each task's objects (the design before: the runtime's own
 * fields, an immutable grid object in a volatile field and a token object): the pool releases
 * thousands of tasks at one instant in index order, and every release reads the grid and writes
 * the next release and the token. Held in three objects per task, that was three objects to
 * reach per release, each a cache miss of its own once the other tasks' releases had pushed it
 * out; held here, a release reads and writes 64 consecutive bytes, and a drain in index order
 * walks the array forward, which the processor's prefetcher follows. The pool's workers also
 * read a batch's next releases and deadlines here without reaching the runtimes at all.
 *
 * <h2>The grid</h2>
 * Release k of task i is at {@code baseNs + (k - baseIndex) * periodNs}, its deadline
 * {@code deadlineNs} later. The grid is anchored once at the start ({@link #anchor}) and, with an
 * adaptive period, re-anchored between two cycles ({@link #reanchor}): release n keeps its time
 * and the releases after it follow the new period.
 *
 * <h2>The deadline token</h2>
 * Which of a periodic task's cycles is running, shared by the thread that runs it and the
 * watchdog so that each miss is reported exactly once: whoever claims a running cycle past its
 * deadline (the watchdog at the deadline, or the cycle's thread when the cycle returns) reports
 * it; a cycle that starts after its deadline is reported by its thread at its start. Odd
 * {@code 2k+1} while cycle k runs; even when none runs (a claim moves {@code 2k+1} to
 * {@code 2k+2}). Volatile stores and compare-and-sets.
 *
 * <h2>Threads</h2>
 * One thread at a time writes a task's grid and next release: the one that runs its cycles
 * (its own thread, or whichever worker the pool hands it to, with a happens-before edge between
 * consecutive ones), with plain stores. Other threads read: the watchdog reads the grid of the
 * cycle the token says is running, after the token's volatile read, so it sees the grid that
 * cycle started with; a grid re-anchored after that cycle ended can be read half-written, but
 * then the token has moved on and the watchdog's claim, a compare-and-set on the token, fails:
 * nothing is reported from such a read. The index of the release a task waits for
 * ({@link #pendingIndex}) is published with an ordered store for the threaded executor's
 * watchdog, which uses it only for when to wake: an older index is an earlier deadline, an early
 * wake. Sized once, at construction; nothing is allocated afterwards.
 */
final class ReleaseTable {

    /** Longs per task: the eight words below, 64 bytes. */
    static final int LONGS_PER_TASK = 8;

    /** The release index at {@link #BASE_NS}. */
    private static final int BASE_INDEX = 0;
    /** The grid's anchor, world time. */
    private static final int BASE_NS = 1;
    /** The period, ns (0 for tasks without a period). */
    private static final int PERIOD_NS = 2;
    /** The relative deadline, ns (0 for tasks without a period). */
    private static final int DEADLINE_NS = 3;
    /** The index of the next release. */
    private static final int NEXT_INDEX = 4;
    /** The world time of the next release, or {@link TaskRuntime#NEVER}. */
    private static final int NEXT_RELEASE_NS = 5;
    /** The deadline token. */
    private static final int TOKEN = 6;
    /** {@link #NEXT_INDEX} as published to the threaded executor's watchdog; -1 when none. */
    private static final int PENDING_INDEX = 7;

    /**
     * Volatile, ordered and compare-and-set access to the words. Invoked on this constant with
     * the exact types ({@code (long) WORDS.getVolatile(long[], int)}), as {@link StatisticsTable}
     * explains.
     */
    private static final VarHandle WORDS = MethodHandles.arrayElementVarHandle(long[].class);

    private final long[] words;

    /** @param size the number of tasks */
    ReleaseTable(int size) {
        words = new long[size * LONGS_PER_TASK];
        for (int task = 0; task < size; task++) {
            words[at(task, NEXT_RELEASE_NS)] = TaskRuntime.NEVER;
            words[at(task, PENDING_INDEX)] = -1;
        }
    }

    private static int at(int task, int word) {
        return task * LONGS_PER_TASK + word;
    }

    // --- the grid ---

    /**
     * Sets a task's period and relative deadline, before its grid is anchored (construction).
     *
     * @param task the task's index
     * @param periodNs the period (0 for tasks without a period)
     * @param deadlineNs the relative deadline (0 for tasks without a period)
     */
    void define(int task, long periodNs, long deadlineNs) {
        words[at(task, PERIOD_NS)] = periodNs;
        words[at(task, DEADLINE_NS)] = deadlineNs;
    }

    /**
     * Anchors a task's grid: release 0 at {@code releaseZeroNs}, with the period and deadline it has.
     *
     * @param task the task's index
     * @param releaseZeroNs the start instant plus the task's offset
     */
    void anchor(int task, long releaseZeroNs) {
        words[at(task, BASE_INDEX)] = 0;
        words[at(task, BASE_NS)] = releaseZeroNs;
    }

    /**
     * Re-anchors a task's grid between two cycles: release {@code n} keeps its time, release
     * {@code n + j} is then at {@code releaseNs(n) + j * newPeriodNs}.
     *
     * @param task the task's index
     * @param n the release that keeps its time
     * @param newPeriodNs the period after it
     * @param newDeadlineNs the relative deadline after it
     */
    void reanchor(int task, long n, long newPeriodNs, long newDeadlineNs) {
        long releaseN = releaseNs(task, n);
        words[at(task, BASE_INDEX)] = n;
        words[at(task, BASE_NS)] = releaseN;
        words[at(task, PERIOD_NS)] = newPeriodNs;
        words[at(task, DEADLINE_NS)] = newDeadlineNs;
    }

    /** @return the world time of release {@code k} of a task */
    long releaseNs(int task, long k) {
        int i = task * LONGS_PER_TASK;
        return words[i + BASE_NS] + (k - words[i + BASE_INDEX]) * words[i + PERIOD_NS];
    }

    /** @return the absolute deadline of release {@code k} of a task */
    long deadlineOf(int task, long k) {
        return releaseNs(task, k) + words[at(task, DEADLINE_NS)];
    }

    /** @return the grid's anchor: release 0's time until a re-anchor; a task without a period's only release */
    long baseNs(int task) {
        return words[at(task, BASE_NS)];
    }

    /** @return a task's period now, ns (0 for tasks without a period) */
    long periodNs(int task) {
        return words[at(task, PERIOD_NS)];
    }

    /** @return a task's relative deadline now, ns (0 for tasks without a period) */
    long deadlineNs(int task) {
        return words[at(task, DEADLINE_NS)];
    }

    /**
     * The skip rule: the release after release {@code k} whose cycle ended at {@code endNs} is
     * the next grid point, or, if the cycle overran it, the first grid point at or after the end.
     *
     * @param task the task's index
     * @param k the release just run
     * @param endNs when its cycle ended
     * @return the index of the next release to run ({@code k + 1} unless releases were skipped)
     */
    long nextAfter(int task, long k, long endNs) {
        int i = task * LONGS_PER_TASK;
        long baseIndex = words[i + BASE_INDEX];
        long periodNs = words[i + PERIOD_NS];
        long next = k + 1;
        long since = endNs - words[i + BASE_NS];
        if (since > (next - baseIndex) * periodNs) {
            // ceil: the first grid point >= end
            return baseIndex + Math.floorDiv(since + periodNs - 1, periodNs);
        }
        return next;
    }

    // --- the next release ---

    /** @return the index of a task's next release */
    long nextIndex(int task) {
        return words[at(task, NEXT_INDEX)];
    }

    /** @return the world time of a task's next release, or {@link TaskRuntime#NEVER} */
    long nextReleaseNs(int task) {
        return words[at(task, NEXT_RELEASE_NS)];
    }

    /**
     * @return the absolute deadline of a periodic task's next release, or {@link TaskRuntime#NEVER}
     *     if it is not released again
     */
    long nextDeadlineNs(int task) {
        int i = task * LONGS_PER_TASK;
        return words[i + NEXT_RELEASE_NS] == TaskRuntime.NEVER ? TaskRuntime.NEVER
                : deadlineOf(task, words[i + NEXT_INDEX]);
    }

    /**
     * Sets a task's next release (the thread that runs its cycles).
     *
     * @param task the task's index
     * @param k its index
     * @param releaseNs its world time, or {@link TaskRuntime#NEVER}
     */
    void next(int task, long k, long releaseNs) {
        int i = task * LONGS_PER_TASK;
        words[i + NEXT_INDEX] = k;
        words[i + NEXT_RELEASE_NS] = releaseNs;
    }

    /**
     * Publishes the index of the release a periodic task waits for, for a watchdog on another
     * thread: an ordered store (no fence).
     *
     * @param task the task's index
     * @param k the release's index, or -1 before the start and once it is never released again
     */
    void publishPendingIndex(int task, long k) {
        WORDS.setRelease(words, at(task, PENDING_INDEX), k);
    }

    /** @return the index {@link #publishPendingIndex} published last, or -1 */
    long pendingIndex(int task) {
        return (long) WORDS.getAcquire(words, at(task, PENDING_INDEX));
    }

    // --- the deadline token ---

    /** Marks cycle {@code k} of a task running (the cycle's thread). */
    void startCycle(int task, long k) {
        WORDS.setVolatile(words, at(task, TOKEN), 2 * k + 1);
    }

    /**
     * Starts cycle {@code k} of a task whose deadline had already passed when it started (the
     * cycle's thread): its miss is certain and the caller reports it now, so the cycle is never
     * seen as running: the watchdog has nothing to claim and {@link #finishCycle} returns false.
     */
    void startCycleAlreadyMissed(int task, long k) {
        WORDS.setVolatile(words, at(task, TOKEN), 2 * k + 2);
    }

    /**
     * Ends cycle {@code k} of a task (the cycle's thread).
     *
     * @return true if the watchdog had not claimed it: a late end is then the caller's to report
     */
    boolean finishCycle(int task, long k) {
        return WORDS.compareAndSet(words, at(task, TOKEN), 2 * k + 1, 2 * k + 2);
    }

    /** @return the index of a task's running cycle, or -1 if none runs */
    long runningCycle(int task) {
        long token = (long) WORDS.getVolatile(words, at(task, TOKEN));
        return (token & 1) == 1 ? (token - 1) >>> 1 : -1;
    }

    /**
     * Claims cycle {@code k} of a task for the watchdog if it is still the running one.
     *
     * @return true if claimed: the caller reports its miss
     */
    boolean claimCycle(int task, long k) {
        return WORDS.compareAndSet(words, at(task, TOKEN), 2 * k + 1, 2 * k + 2);
    }
}
