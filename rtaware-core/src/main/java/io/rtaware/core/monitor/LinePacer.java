package io.rtaware.core.monitor;

/**
 * When the next line of one stream of reports may be printed, so that a terminal stays readable
 * (wall time: the limit protects a person reading). After a line, the next waits the current
 * interval; while the reports keep coming (a line is due and there is something to print), the
 * interval doubles, up to the longest; after a calm spell (a line was due and there was nothing to
 * print: {@link #calm()}) the next line is printed at once and the wait starts over at the first.
 * Events in between are the caller's to fold into the next line: nothing is dropped, only held back.
 * Not thread-safe: one printer uses it.
 */
final class LinePacer {

    private final long firstIntervalNs;
    private final long longestIntervalNs;
    private long intervalNs;
    private long lastLineNs;
    private boolean printedAny;
    private boolean calm;

    /**
     * @param firstIntervalNs the wait after a first line, and after a calm spell
     * @param longestIntervalNs the longest wait while reports keep coming (equal to the first for
     *     a fixed rate)
     */
    LinePacer(long firstIntervalNs, long longestIntervalNs) {
        if (firstIntervalNs <= 0 || longestIntervalNs < firstIntervalNs) {
            throw new IllegalArgumentException("intervals must be positive and the longest at least the first, got "
                    + firstIntervalNs + " ns and " + longestIntervalNs + " ns");
        }
        this.firstIntervalNs = firstIntervalNs;
        this.longestIntervalNs = longestIntervalNs;
        this.intervalNs = firstIntervalNs;
    }

    /**
     * @param nowNs the wall clock now
     * @return true if a line may be printed now
     */
    boolean due(long nowNs) {
        return !printedAny || nowNs - lastLineNs >= intervalNs;
    }

    /**
     * Records a line printed now and sets the wait before the next.
     *
     * @param nowNs the wall clock now
     * @return the time since the previous line (the span this line's counts cover), 0 for the first
     */
    long printed(long nowNs) {
        long sinceNs = printedAny ? nowNs - lastLineNs : 0;
        intervalNs = printedAny && !calm ? Math.min(2 * intervalNs, longestIntervalNs) : firstIntervalNs;
        lastLineNs = nowNs;
        printedAny = true;
        calm = false;
        return sinceNs;
    }

    /** Records that a line was due and there was nothing to print: the next line starts the waits over. */
    void calm() {
        calm = true;
        intervalNs = firstIntervalNs;
    }

    /**
     * Records, later, a moment at which there was nothing to print: the same as {@link #calm()}
     * called then, if a line was due then (and none has been printed since). For a printer that
     * skips its look at the pacers while nothing happens at all.
     *
     * @param quietNs the wall clock at that moment
     */
    void calmIfDueAt(long quietNs) {
        if (due(quietNs) && (!printedAny || quietNs > lastLineNs)) {
            calm();
        }
    }

    /** @return the wait before the next line may be printed */
    long intervalNs() {
        return intervalNs;
    }
}
