package io.rtaware.experiment;

import java.io.PrintStream;
import java.util.Locale;
import java.util.function.LongSupplier;

/**
 * The experiment's progress on stderr: runs done of total, the run under way, the last outcome
 * and an ETA. On a terminal one line is redrawn in place; otherwise a line is printed per event.
 * The ETA is the mean wall time of the runs finished in this session times the runs left; before
 * the first run finishes it is the worst case, a whole time limit per run.
 */
public final class ProgressBar {

    private static final int WIDTH = 20;

    private final PrintStream out;
    private final boolean inPlace;
    private final LongSupplier nanoTime;
    private final double worstCaseRunS;
    private long startNs = -1;
    private int finishedHere;
    private String last = "none yet";

    /**
     * @param out where to draw
     * @param inPlace redraw one line with carriage returns (true on a terminal)
     * @param nanoTime a monotonic clock, e.g. {@code System::nanoTime}
     * @param worstCaseRunS wall seconds a run may take at most, for the first ETA
     */
    public ProgressBar(PrintStream out, boolean inPlace, LongSupplier nanoTime, double worstCaseRunS) {
        this.out = out;
        this.inPlace = inPlace;
        this.nanoTime = nanoTime;
        this.worstCaseRunS = worstCaseRunS;
    }

    /**
     * @param run the run starting
     * @param done runs already in the results
     * @param total runs in the experiment
     */
    public void started(PlannedRun run, int done, int total) {
        if (startNs < 0) {
            startNs = nanoTime.getAsLong();
        }
        draw(line(done, total, "set " + run.set() + " (" + run.periods().name() + ") run " + run.run(), eta(total - done)));
    }

    /**
     * @param result the run that finished
     * @param done runs in the results now
     * @param total runs in the experiment
     */
    public void finished(RunResult result, int done, int total) {
        finishedHere++;
        last = "set " + result.set() + " run " + result.run() + " " + result.outcome()
                + (Double.isFinite(result.runTimeS()) ? String.format(Locale.ROOT, " %.1f s", result.runTimeS()) : "");
        draw(line(done, total, "", eta(total - done)));
    }

    /**
     * Shows why the next run waits, on the progress line (in place on a terminal).
     *
     * @param reason one line, e.g. {@code waiting for a quiet machine (...)}
     */
    public void waiting(String reason) {
        draw("[waiting] " + reason);
    }

    /**
     * Prints a message on its own line (a failed run, an interruption).
     *
     * @param message one line
     */
    public void note(String message) {
        if (inPlace) {
            out.print("\r\033[K");
        }
        out.println(message);
        out.flush();
    }

    /** Ends the in-place line. */
    public void close() {
        if (inPlace) {
            out.println();
            out.flush();
        }
    }

    /**
     * @param done runs finished
     * @param total runs in all
     * @param current the run under way, or empty
     * @param etaS seconds left
     * @return the progress line
     */
    String line(int done, int total, String current, double etaS) {
        int filled = total == 0 ? WIDTH : (int) Math.round(WIDTH * (double) done / total);
        String bar = "#".repeat(filled) + ".".repeat(WIDTH - filled);
        return "[" + bar + "] " + done + "/" + total + (current.isEmpty() ? "" : " | running " + current)
                + " | last: " + last + " | ETA " + duration(etaS);
    }

    private double eta(int left) {
        if (finishedHere == 0) {
            return left * worstCaseRunS;
        }
        double perRunS = (nanoTime.getAsLong() - startNs) / 1e9 / finishedHere;
        return left * perRunS;
    }

    /**
     * @param seconds a duration
     * @return {@code h:mm:ss}
     */
    static String duration(double seconds) {
        long s = Math.max(0, Math.round(seconds));
        return String.format(Locale.ROOT, "%d:%02d:%02d", s / 3600, (s / 60) % 60, s % 60);
    }

    private void draw(String line) {
        if (inPlace) {
            out.print("\r\033[K" + line);
        } else {
            out.println(line);
        }
        out.flush();
    }
}
