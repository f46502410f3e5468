package io.rtaware.live;

import io.rtaware.core.monitor.CycleOutcome;
import io.rtaware.core.monitor.MonitorListener;
import io.rtaware.core.monitor.TaskInfo;
import java.lang.invoke.VarHandle;
import java.util.Arrays;
import java.util.concurrent.atomic.AtomicLong;

/**
 * Each task's release lateness and execution time over the last {@value #WINDOW_BINS} bins of
 * {@value #BIN_NS} ns of world time (a minute), with its misses, for the live page's strip charts.
 *
 * <p>As a {@link MonitorListener} it copies every cycle record, and every skip of releases, into
 * the task's ring of primitives, on the task's own thread: a few stores and a release store of
 * the counts, no allocation, no lock, nothing that waits for the page. The publisher thread
 * ({@link #drain}) copies out what the rings hold since its last look and adds it to bins by
 * release time; a ring the publisher fell a whole ring behind on has been overwritten, and the
 * cycles lost so are counted ({@link Bins#lost}), never drawn wrong. A cycle that missed its
 * deadline, and every skipped release, is a miss of the bin its release fell in.
 *
 * <p>Threads: the listener methods on each task's thread (one at a time per task, as the monitor
 * runs a task's cycles); {@link #drain} and {@link #bins} on one observer thread.
 */
final class TimingSeries implements MonitorListener {

    /** World time of one bin: 0.5 s. */
    static final long BIN_NS = 500_000_000L;
    /** Bins kept and shown: 120, a minute of world time. */
    static final int WINDOW_BINS = 120;
    /** Cycle records a task's ring holds; a power of two. */
    static final int RING_SLOTS = 4096;
    private static final int MASK = RING_SLOTS - 1;

    private final long originNs;
    private final Ring[] rings;
    private final Bins[] bins;
    /** The publisher's copy of a ring's records (one ring at a time). */
    private final long[] scratchRelease = new long[RING_SLOTS];
    private final long[] scratchLateness = new long[RING_SLOTS];
    private final long[] scratchExec = new long[RING_SLOTS];
    private final long[] scratchMisses = new long[RING_SLOTS];
    private final boolean[] scratchRan = new boolean[RING_SLOTS];

    /**
     * @param tasks how many tasks (their indexes are {@link TaskInfo#index()})
     * @param originNs world time of bin 0's start
     */
    TimingSeries(int tasks, long originNs) {
        this.originNs = originNs;
        rings = new Ring[tasks];
        bins = new Bins[tasks];
        for (int i = 0; i < tasks; i++) {
            rings[i] = new Ring();
            bins[i] = new Bins();
        }
    }

    /** One task's cycle records: written by its thread, read by the publisher. */
    private static final class Ring {
        final long[] releaseNs = new long[RING_SLOTS];
        final long[] latenessNs = new long[RING_SLOTS];
        final long[] execNs = new long[RING_SLOTS];
        /** Misses of the record: 1 for a cycle past its deadline, the count for skipped releases. */
        final long[] misses = new long[RING_SLOTS];
        /** False for a record of skipped releases (no lateness or execution time). */
        final boolean[] ran = new boolean[RING_SLOTS];
        /** Records begun: record n may be being written into slot {@code n & MASK} once this is above n. */
        final AtomicLong claimed = new AtomicLong();
        /** Records written; record n is in slot {@code n & MASK}, complete once this is above n. */
        final AtomicLong published = new AtomicLong();
        /** Records the publisher has taken (publisher only). */
        long taken;

        void put(long release, long lateness, long exec, long missCount, boolean cycle) {
            long n = published.get();
            claimed.lazySet(n + 1);
            VarHandle.storeStoreFence(); // the claim before the slot's fields: the publisher sees what it may have read torn
            int slot = (int) (n & MASK);
            releaseNs[slot] = release;
            latenessNs[slot] = lateness;
            execNs[slot] = exec;
            misses[slot] = missCount;
            ran[slot] = cycle;
            published.lazySet(n + 1); // a release store: the slot's fields before the count
        }
    }

    /** One task's bins (publisher only). */
    static final class Bins {
        private static final int SLOTS = WINDOW_BINS + 1;
        private final long[] index = new long[SLOTS];
        private final long[] cycles = new long[SLOTS];
        private final long[] misses = new long[SLOTS];
        private final long[] maxLatenessNs = new long[SLOTS];
        private final long[] maxExecNs = new long[SLOTS];
        private long newest = -1;
        private long lost;

        Bins() {
            Arrays.fill(index, -1);
        }

        private void add(long bin, long latenessNs, long execNs, long missCount, boolean ran) {
            if (bin < 0 || bin <= newest - SLOTS) {
                return; // before the view began, or older than the window
            }
            int slot = (int) (bin % SLOTS);
            if (index[slot] != bin) {
                index[slot] = bin;
                cycles[slot] = 0;
                misses[slot] = 0;
                maxLatenessNs[slot] = 0;
                maxExecNs[slot] = 0;
            }
            newest = Math.max(newest, bin);
            misses[slot] += missCount;
            if (ran) {
                cycles[slot]++;
                maxLatenessNs[slot] = Math.max(maxLatenessNs[slot], latenessNs);
                maxExecNs[slot] = Math.max(maxExecNs[slot], execNs);
            }
        }

        /**
         * @param bin a bin number
         * @return cycles whose release fell in it (0 if none, or if it is out of the window)
         */
        long cycles(long bin) {
            int slot = (int) (bin % SLOTS);
            return bin >= 0 && index[slot] == bin ? cycles[slot] : 0;
        }

        /**
         * @param bin a bin number
         * @return misses of releases in it: cycles that ended after their deadline and skipped releases
         */
        long misses(long bin) {
            int slot = (int) (bin % SLOTS);
            return bin >= 0 && index[slot] == bin ? misses[slot] : 0;
        }

        /**
         * @param bin a bin number with {@link #cycles} above 0
         * @return the largest release lateness (start minus release) of its cycles, ns
         */
        long maxLatenessNs(long bin) {
            return maxLatenessNs[(int) (bin % SLOTS)];
        }

        /**
         * @param bin a bin number with {@link #cycles} above 0
         * @return the longest execution time (end minus start) of its cycles, ns
         */
        long maxExecNs(long bin) {
            return maxExecNs[(int) (bin % SLOTS)];
        }

        /** @return cycle records overwritten before the publisher took them */
        long lost() {
            return lost;
        }
    }

    @Override
    public void onCycleRecord(TaskInfo task, CycleOutcome outcome, long releaseNs, long startNs, long endNs,
                              long[] inputGenerations) {
        rings[task.index()].put(releaseNs, startNs - releaseNs, endNs - startNs, outcome == CycleOutcome.MISS ? 1 : 0,
                true);
    }

    @Override
    public void onSkippedReleases(TaskInfo task, long skipped, long nowNs) {
        rings[task.index()].put(nowNs, 0, 0, skipped, false);
    }

    /**
     * @param worldNs a world time
     * @return the number of the bin it falls in (negative before the origin)
     */
    long binOf(long worldNs) {
        return Math.floorDiv(worldNs - originNs, BIN_NS);
    }

    /** @return world time of bin 0's start */
    long originNs() {
        return originNs;
    }

    /** Takes every record the rings hold since the last call into the bins. Publisher thread only. */
    void drain() {
        for (int t = 0; t < rings.length; t++) {
            Ring ring = rings[t];
            Bins into = bins[t];
            long end = ring.published.get();
            long from = Math.max(ring.taken, end - RING_SLOTS);
            for (long n = from; n < end; n++) {
                int slot = (int) (n & MASK);
                int k = (int) (n - from);
                scratchRelease[k] = ring.releaseNs[slot];
                scratchLateness[k] = ring.latenessNs[slot];
                scratchExec[k] = ring.execNs[slot];
                scratchMisses[k] = ring.misses[slot];
                scratchRan[k] = ring.ran[slot];
            }
            VarHandle.acquireFence(); // the copies above before the claim below
            long valid = Math.max(from, ring.claimed.get() - RING_SLOTS); // older slots were rewritten while copied
            into.lost += valid - ring.taken;
            for (long n = valid; n < end; n++) {
                int k = (int) (n - from);
                into.add(binOf(scratchRelease[k]), scratchLateness[k], scratchExec[k], scratchMisses[k], scratchRan[k]);
            }
            ring.taken = end;
        }
    }

    /**
     * @param task a task index
     * @return its bins (publisher thread only)
     */
    Bins bins(int task) {
        return bins[task];
    }
}
