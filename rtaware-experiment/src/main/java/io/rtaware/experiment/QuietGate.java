package io.rtaware.experiment;

import io.rtaware.core.conditions.MachineVerdict;
import java.util.Locale;
import java.util.Objects;
import java.util.function.BooleanSupplier;
import java.util.function.LongSupplier;

/**
 * Before each run of an experiment: checks the machine and, unless busy runs are allowed, waits
 * until it is quiet, at most {@code maxWaitS}, saying on the progress line why it waits. A run
 * made after the wait ran out, or with busy runs allowed, is labelled by its check
 * ({@code machine_before_run}) and by its own measured conditions; the summary leaves out runs
 * that were not quiet unless asked to include them.
 */
public final class QuietGate {

    /** Time between two checks while waiting, s. */
    public static final double RETRY_S = 5;

    /** Waits for the given time; a test's fake advances a clock instead. */
    @FunctionalInterface
    public interface Sleeper {
        /**
         * @param seconds how long
         * @throws InterruptedException if interrupted
         */
        void sleep(double seconds) throws InterruptedException;
    }

    /**
     * What the gate found before a run.
     *
     * @param beforeRun the verdict of the last check ({@code quiet}, {@code busy}, ...)
     * @param waitedS how long it waited, s
     * @param reason the last check's line, e.g. {@code machine: busy (other processes used ...)}
     * @param otherCpus the last check's other processes' CPU, CPUs ({@link MachineCheck.Reading}), or NaN
     * @param stealPct the last check's steal, percent, or NaN
     * @param load1 the last check's load average, or NaN
     */
    public record Passage(String beforeRun, double waitedS, String reason, double otherCpus, double stealPct,
                          double load1) {

        static Passage of(MachineCheck.Reading r, double waitedS) {
            return new Passage(r.verdict().verdict(), waitedS, r.verdict().text(), r.otherCpus(), r.stealPct(), r.load1());
        }
    }

    private final MachineCheck check;
    private final Sleeper sleeper;
    private final LongSupplier nanoTime;
    private final double maxWaitS;
    private final boolean allowBusy;

    /**
     * @param check the check of the machine
     * @param sleeper how to wait between checks
     * @param nanoTime a monotonic clock
     * @param maxWaitS the longest wait for a quiet machine before a run, s
     * @param allowBusy true to run without waiting (the run is labelled)
     */
    public QuietGate(MachineCheck check, Sleeper sleeper, LongSupplier nanoTime, double maxWaitS, boolean allowBusy) {
        this.check = Objects.requireNonNull(check, "check");
        this.sleeper = Objects.requireNonNull(sleeper, "sleeper");
        this.nanoTime = Objects.requireNonNull(nanoTime, "nanoTime");
        if (!(maxWaitS >= 0)) {
            throw new IllegalArgumentException("the wait for a quiet machine must be >= 0 s, got " + maxWaitS);
        }
        this.maxWaitS = maxWaitS;
        this.allowBusy = allowBusy;
    }

    /**
     * @param progress where the waiting is shown
     * @param stopped true once the experiment is interrupted (Ctrl-C): the wait ends at the next check
     * @return the verdict the run starts with, and how long it waited
     * @throws InterruptedException if interrupted while waiting
     */
    public Passage await(ProgressBar progress, BooleanSupplier stopped) throws InterruptedException {
        long start = nanoTime.getAsLong();
        while (!stopped.getAsBoolean()) {
            MachineCheck.Reading reading = check.check();
            MachineVerdict v = reading.verdict();
            double waited = (nanoTime.getAsLong() - start) / 1e9;
            if (v.quiet() || MachineVerdict.UNKNOWN.equals(v.verdict()) || allowBusy) {
                return Passage.of(reading, waited);
            }
            if (waited >= maxWaitS) {
                progress.note(String.format(Locale.ROOT, "waited %.0f s for a quiet machine, the most allowed "
                        + "(--quiet-wait); running anyway, labelled: %s", waited, v.text()));
                return Passage.of(reading, waited);
            }
            progress.waiting(String.format(Locale.ROOT, "waiting for a quiet machine (%.0f of at most %.0f s): %s",
                    waited, maxWaitS, v.text()));
            sleeper.sleep(Math.min(RETRY_S, Math.max(0, maxWaitS - waited)));
        }
        return new Passage("interrupted", (nanoTime.getAsLong() - start) / 1e9, "interrupted while waiting", Double.NaN,
                Double.NaN, Double.NaN);
    }
}
