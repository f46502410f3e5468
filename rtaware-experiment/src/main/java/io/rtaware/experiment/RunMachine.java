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
 */
public record RunMachine(String machine, String reasons, double otherCpus, double stealPct, double loadStart,
                         double loadEnd, double gcMaxPauseMs, double timeToSafepointMaxMs, String beforeRun,
                         double waitedS, int machineCpus) {

    /** The verdict of a run whose conditions were not recorded. */
    public static final String UNRECORDED = "unrecorded";
    /** The verdict of a quiet run. */
    public static final String QUIET = "quiet";

    /** The machine of a run whose conditions were not recorded. */
    public static final RunMachine NOT_RECORDED = new RunMachine(UNRECORDED, "", Double.NaN, Double.NaN, Double.NaN,
            Double.NaN, Double.NaN, Double.NaN, "", 0, 0);

    /** Verdicts a summary includes by default. */
    static final Set<String> INCLUDED_BY_DEFAULT = Set.of(QUIET);

    /** @return true if the run's own conditions say the machine was quiet */
    public boolean quiet() {
        return QUIET.equals(machine);
    }

    /**
     * @param beforeRun the verdict of the check before the run
     * @param waitedS the time waited for quiet
     * @return this with the check before the run
     */
    public RunMachine withCheck(String beforeRun, double waitedS) {
        return new RunMachine(machine, reasons, otherCpus, stealPct, loadStart, loadEnd, gcMaxPauseMs,
                timeToSafepointMaxMs, beforeRun, waitedS, machineCpus);
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
