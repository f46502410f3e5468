package io.rtaware.experiment;

import io.rtaware.core.conditions.MachineVerdict;
import java.util.Optional;
import java.util.Set;

/**
 * The machine during one run of an experiment: the verdict of the run's own {@code conditions}
 * (its report.json) and the figures behind it, and what the check before the run found. A run
 * made before rtaware recorded conditions has {@link #UNRECORDED}.
 *
 * @param machine {@code quiet}, {@code busy}, {@code disturbed}, {@code unknown}, or
 *     {@link #UNRECORDED}
 * @param reasons the figures that crossed their thresholds (or, quiet, the figures), "; "-joined
 * @param otherCpus CPU used by other processes during the run, CPUs, or NaN
 * @param stealPct steal during the run, percent, or NaN
 * @param loadStart load average at the run's start, or NaN
 * @param loadEnd load average at its end, or NaN
 * @param gcMaxPauseMs the run's longest GC pause, ms, or NaN
 * @param timeToSafepointMaxMs the run's longest time to safepoint, ms, or NaN
 * @param beforeRun the verdict of the check before the run ({@code quiet}, {@code busy}), or
 *     empty when none was made
 * @param waitedS how long the experiment waited for a quiet machine before the run, s
 * @param machineCpus the CPUs the OS counted during the run (its conditions' {@code machine_cpus}),
 *     or 0 where not recorded
 * @param checkOtherCpus other processes' CPU in the last check before the run, CPUs: the corrected
 *     figure the quiet rule judged ({@link MachineCheck.Reading#otherCpus()}), or NaN where no check
 *     was made or recorded
 * @param checkStealPct steal in that check, percent, or NaN
 * @param checkLoad the load average at that check's end, or NaN
 */
public record RunMachine(String machine, String reasons, double otherCpus, double stealPct, double loadStart,
                         double loadEnd, double gcMaxPauseMs, double timeToSafepointMaxMs, String beforeRun,
                         double waitedS, int machineCpus, double checkOtherCpus, double checkStealPct,
                         double checkLoad) {

    /** The verdict of a run whose conditions were not recorded. */
    public static final String UNRECORDED = "unrecorded";
    /** The verdict of a quiet run. */
    public static final String QUIET = "quiet";

    /** The machine of a run whose conditions were not recorded. */
    public static final RunMachine NOT_RECORDED = new RunMachine(UNRECORDED, "", Double.NaN, Double.NaN, Double.NaN,
            Double.NaN, Double.NaN, Double.NaN, "", 0, 0);

    /**
     * The machine of a run without the readings of a check before it.
     *
     * @param machine the run's verdict
     * @param reasons the figures behind it
     * @param otherCpus other processes' CPU during the run, CPUs, or NaN
     * @param stealPct steal during the run, percent, or NaN
     * @param loadStart load average at the start, or NaN
     * @param loadEnd load average at the end, or NaN
     * @param gcMaxPauseMs longest GC pause, ms, or NaN
     * @param timeToSafepointMaxMs longest time to safepoint, ms, or NaN
     * @param beforeRun the verdict of the check before the run, or empty
     * @param waitedS time waited for quiet, s
     * @param machineCpus the CPUs counted, or 0
     */
    public RunMachine(String machine, String reasons, double otherCpus, double stealPct, double loadStart,
                      double loadEnd, double gcMaxPauseMs, double timeToSafepointMaxMs, String beforeRun,
                      double waitedS, int machineCpus) {
        this(machine, reasons, otherCpus, stealPct, loadStart, loadEnd, gcMaxPauseMs, timeToSafepointMaxMs, beforeRun,
                waitedS, machineCpus, Double.NaN, Double.NaN, Double.NaN);
    }

    /** Verdicts a summary includes by default. */
    static final Set<String> INCLUDED_BY_DEFAULT = Set.of(QUIET);

    /** @return true if the run's own conditions say the machine was quiet */
    public boolean quiet() {
        return QUIET.equals(machine);
    }

    /**
     * @param check what the check before the run found
     * @return this with the check's verdict, wait and readings
     */
    public RunMachine withCheck(QuietGate.Passage check) {
        return new RunMachine(machine, reasons, otherCpus, stealPct, loadStart, loadEnd, gcMaxPauseMs,
                timeToSafepointMaxMs, check.beforeRun(), check.waitedS(), machineCpus, check.otherCpus(), check.stealPct(),
                check.load1());
    }

    /**
     * @return why these figures cannot be what a run measured, or empty: other processes used
     *     more CPUs than the machine has, or a figure is negative, or the verdict is not the one
     *     {@link MachineVerdict}'s rule gives them ({@code quiet} or {@code disturbed} although
     *     other processes or steal crossed the threshold of {@code busy})
     */
    public Optional<String> impossible() {
        if (machineCpus < 0) {
            return Optional.of("machine_cpus " + machineCpus + " cannot be negative");
        }
        if (otherCpus < 0 || stealPct < 0) {
            return Optional.of("other_cpus " + otherCpus + " and steal_pct " + stealPct + " cannot be negative");
        }
        if (checkOtherCpus < 0 || checkStealPct < 0 || checkLoad < 0) {
            return Optional.of("check_other_cpus " + checkOtherCpus + ", check_steal_pct " + checkStealPct
                    + " and check_load " + checkLoad + " cannot be negative");
        }
        if (machineCpus > 0 && otherCpus > machineCpus) {
            return Optional.of("other_cpus " + otherCpus + " is more than the machine's " + machineCpus
                    + " CPUs (machine_cpus)");
        }
        boolean busyByRule = otherCpus > MachineVerdict.OTHER_CPUS_MAX || stealPct > MachineVerdict.STEAL_MAX_PCT;
        if (busyByRule && (quiet() || MachineVerdict.DISTURBED.equals(machine))) {
            return Optional.of("labelled " + machine + " but other_cpus " + otherCpus + " and steal_pct " + stealPct
                    + " make it busy by the rule (" + MachineVerdict.RULE + ")");
        }
        return Optional.empty();
    }
}
