package io.rtaware.bench.compare;

import org.HdrHistogram.AbstractHistogram;
import org.HdrHistogram.IntCountsHistogram;

/**
 * The comparison's bookkeeping for one task under one executor, fed with every run's intended
 * release, start and end (all in {@link System#nanoTime()} nanoseconds), and with the releases
 * an executor skipped. The same rules apply to every executor:
 * <ul>
 *   <li><b>lateness</b> = start - intended release (never start - previous start, so a stall is
 *   not hidden), clamped at 0;</li>
 *   <li><b>miss</b> = a run that finished after {@code release + period}, plus every skipped
 *   release;</li>
 *   <li><b>burst</b> = a run that started less than half a period after the previous run of the
 *   same task.</li>
 * </ul>
 * Only releases inside the measurement window {@code [fromNs, untilNs)} are counted, so thread
 * start-up and shutdown stay out of the numbers.
 *
 * <p>Allocation-free after construction. Written by one task thread at a time; read by the
 * coordinator after that thread has stopped (the join publishes the values). The thread id is
 * volatile so the coordinator can find the thread while it runs.
 */
public final class ReleaseStats {

    /** Lowest lateness told apart: 1 us. Lateness is reported in microseconds. */
    static final long LOWEST_DISCERNIBLE_NS = 1_000;
    /** Largest lateness recorded exactly; larger values are clamped (the exact max is kept). */
    static final long HIGHEST_TRACKABLE_NS = 60_000_000_000L;
    private static final long NO_START = Long.MIN_VALUE;
    /** This object's header and fields, and the histogram object's beyond HdrHistogram's estimate. */
    private static final long FIELDS_BYTES = 256;

    private final long periodNs;
    /**
     * 32-bit counts (half the heap of 64-bit ones, which matters at 10 000 tasks): the histogram
     * is reset every segment and holds at most one value per release in it, so a bucket cannot
     * reach 2^31 unless a segment held 2^31 releases of one task (a 1 us period for 36 minutes).
     */
    private final AbstractHistogram latenessNs = newHistogram();
    /**
     * The window (all of time until the first {@link #reset}), written by the coordinator while
     * the task's thread reads it.
     */
    private volatile long fromNs = Long.MIN_VALUE;
    private volatile long untilNs = Long.MAX_VALUE;
    private long previousStartNs = NO_START;
    private long releases;
    private long misses;
    private long bursts;
    private long maxLatenessNs;
    private volatile long threadId;

    /** @param periodNs the task's period (its deadline too) */
    public ReleaseStats(long periodNs) {
        if (periodNs <= 0) {
            throw new IllegalArgumentException(CheckText.badPeriod(periodNs));
        }
        this.periodNs = periodNs;
    }

    /**
     * The constructor's check's text, in a class of its own: kept in this class's constants, a
     * message built only when the check fails was resolved (88 bytes allocated) on the task thread
     * whose call of {@link #onRun} had it compiled by C2, inside a measured window, which the
     * comparison counts as the framework's allocation (found with {@code scripts/alloc-probe.c}).
     */
    private static final class CheckText {
        static String badPeriod(long periodNs) {
            return "period must be positive, got " + periodNs + " ns";
        }
    }

    /**
     * Clears every count and closes the window (nothing is counted until {@link #openWindow});
     * call before the segment's threads start.
     */
    public void reset() {
        latenessNs.reset();
        fromNs = Long.MAX_VALUE;
        untilNs = Long.MAX_VALUE;
        previousStartNs = NO_START;
        releases = 0;
        misses = 0;
        bursts = 0;
        maxLatenessNs = 0;
        threadId = 0;
    }

    /**
     * Sets the measurement window while the segment's threads run; call before {@code
     * windowFromNs} (a release before it is not counted whichever window its thread saw).
     *
     * @param windowFromNs first intended release counted
     * @param windowUntilNs releases at or after this are not counted
     */
    public void openWindow(long windowFromNs, long windowUntilNs) {
        untilNs = windowUntilNs;
        fromNs = windowFromNs;
    }

    /**
     * Records one run; call on the thread that ran it.
     *
     * @param releaseNs the intended release
     * @param startNs when the run started
     * @param endNs when it finished
     */
    public void onRun(long releaseNs, long startNs, long endNs) {
        if (threadId == 0) {
            threadId = Thread.currentThread().getId();
        }
        boolean burst = previousStartNs != NO_START && startNs - previousStartNs < periodNs / 2;
        previousStartNs = startNs;
        if (releaseNs < fromNs || releaseNs >= untilNs) {
            return;
        }
        releases++;
        if (burst) {
            bursts++;
        }
        long lateness = Math.max(0, startNs - releaseNs);
        latenessNs.recordValue(Math.min(Math.max(lateness, LOWEST_DISCERNIBLE_NS), HIGHEST_TRACKABLE_NS));
        if (lateness > maxLatenessNs) {
            maxLatenessNs = lateness;
        }
        if (endNs > releaseNs + periodNs) {
            misses++;
        }
    }

    /**
     * Records releases the executor passed over without running them; each is a release and a
     * miss.
     *
     * @param count how many
     * @param nowNs when they were skipped (decides whether they fall in the window)
     */
    public void onSkipped(long count, long nowNs) {
        if (nowNs >= fromNs && nowNs < untilNs) {
            releases += count;
            misses += count;
        }
    }

    /** @return releases counted in the window */
    public long releases() {
        return releases;
    }

    /** @return misses counted in the window */
    public long misses() {
        return misses;
    }

    /** @return bursts counted in the window */
    public long bursts() {
        return bursts;
    }

    /** @return the exact largest lateness in the window, ns */
    public long maxLatenessNs() {
        return maxLatenessNs;
    }

    /** @return the id of the thread that last ran the task, or 0 before its first run */
    public long threadId() {
        return threadId;
    }

    /** @return heap bytes one instance takes (its histogram, as HdrHistogram estimates it, and its fields) */
    public static long estimatedHeapBytes() {
        return newHistogram().getEstimatedFootprintInBytes() + FIELDS_BYTES;
    }

    private static AbstractHistogram newHistogram() {
        return new IntCountsHistogram(LOWEST_DISCERNIBLE_NS, HIGHEST_TRACKABLE_NS, 2);
    }

    /** @return the lateness histogram (ns, 1 us resolution, 2 significant digits) */
    AbstractHistogram latenessNs() {
        return latenessNs;
    }
}
