package io.rtaware.experiment;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.ToDoubleFunction;

/**
 * The {@code conditions} of an experiment's summary: how many runs were made on a quiet, busy
 * or disturbed machine, which of them the summary uses and why the others were left out, and
 * the spread over the used runs of what disturbed them.
 *
 * @param includeBusy true if the summary uses every run ({@code --include-busy}); false: only
 *     the quiet ones
 * @param rule which runs count as quiet
 * @param runs runs in the results
 * @param byMachine runs per verdict of their own conditions ({@code quiet}, {@code busy},
 *     {@code disturbed}, {@code unknown}, {@code unrecorded})
 * @param used runs the summary, tables, t-tests and claims use
 * @param quietUsed how many of the used runs count as quiet ({@link #countsAsQuiet}); 0 with
 *     {@code used > 0} is a report made only of busy runs ({@link #busyOnly()})
 * @param leftOut each run left out, with the reason
 * @param otherCpus CPU used by other processes during the used runs, CPUs
 * @param stealPct steal during the used runs, percent
 * @param loadStart the load average at the start of the used runs
 * @param gcMaxPauseMs the longest GC pause of each used run, ms
 * @param timeToSafepointMaxMs the longest time to safepoint of each used run, ms
 * @param waitedForQuietS the time waited for a quiet machine before each used run, s
 */
public record ExperimentConditions(boolean includeBusy, String rule, int runs, Map<String, Integer> byMachine, int used,
                                   int quietUsed, List<String> leftOut, Spread otherCpus, Spread stealPct, Spread loadStart,
                                   Spread gcMaxPauseMs, Spread timeToSafepointMaxMs, Spread waitedForQuietS) {

    /** Which runs count as quiet, in words. */
    public static final String RULE = "a run counts as quiet when its own measured conditions say quiet (rtaware run's "
            + "machine verdict), or, for a run that left no report, when the check before it found the machine quiet";

    /**
     * Smallest, median and largest of a figure over runs (nulls where no run gave it).
     *
     * @param min the smallest
     * @param median the median
     * @param max the largest
     * @param n runs that gave the figure
     */
    public record Spread(Double min, Double median, Double max, int n) {

        static Spread of(List<RunResult> runs, ToDoubleFunction<RunMachine> figure) {
            double[] v = runs.stream().mapToDouble(r -> figure.applyAsDouble(r.machine())).filter(Double::isFinite)
                    .sorted().toArray();
            if (v.length == 0) {
                return new Spread(null, null, null, 0);
            }
            double median = v.length % 2 == 1 ? v[v.length / 2] : (v[v.length / 2 - 1] + v[v.length / 2]) / 2;
            return new Spread(v[0], median, v[v.length - 1], v.length);
        }
    }

    /**
     * @param r a run
     * @return true if it counts as quiet by {@link #RULE}
     */
    public static boolean countsAsQuiet(RunResult r) {
        RunMachine m = r.machine();
        return m.quiet() || RunMachine.UNRECORDED.equals(m.machine()) && RunMachine.QUIET.equals(m.beforeRun());
    }

    /**
     * @param rows every run of the results
     * @param includeBusy true to use them all
     * @return the runs to summarize
     */
    public static List<RunResult> used(List<RunResult> rows, boolean includeBusy) {
        return includeBusy ? rows : rows.stream().filter(ExperimentConditions::countsAsQuiet).toList();
    }

    /**
     * @param rows every run of the results
     * @param includeBusy true if all are used
     * @return the conditions of the experiment
     */
    public static ExperimentConditions of(List<RunResult> rows, boolean includeBusy) {
        List<RunResult> used = used(rows, includeBusy);
        Map<String, Integer> byMachine = new TreeMap<>();
        rows.forEach(r -> byMachine.merge(r.machine().machine(), 1, Integer::sum));
        List<String> leftOut = new ArrayList<>();
        for (RunResult r : rows) {
            if (!used.contains(r)) {
                RunMachine m = r.machine();
                leftOut.add("set " + r.set() + " run " + r.run() + ": " + m.machine()
                        + (m.reasons().isEmpty() ? RunMachine.UNRECORDED.equals(m.machine())
                        ? " (made before rtaware recorded conditions, or no report)" : "" : " (" + m.reasons() + ")"));
            }
        }
        int quietUsed = (int) used.stream().filter(ExperimentConditions::countsAsQuiet).count();
        return new ExperimentConditions(includeBusy, RULE, rows.size(), byMachine, used.size(), quietUsed, leftOut,
                Spread.of(used, RunMachine::otherCpus), Spread.of(used, RunMachine::stealPct),
                Spread.of(used, RunMachine::loadStart), Spread.of(used, RunMachine::gcMaxPauseMs),
                Spread.of(used, RunMachine::timeToSafepointMaxMs),
                Spread.of(used.stream().filter(r -> !RunMachine.UNRECORDED.equals(r.machine().machine())).toList(),
                        RunMachine::waitedS));
    }

    /** @return true if the report uses runs and not one of them was made on a quiet machine */
    public boolean busyOnly() {
        return used > 0 && quietUsed == 0;
    }

    /**
     * @return the warning a report made only of busy runs opens with, e.g. {@code Not one run of this
     *     report was made on a machine known to be quiet (2 busy): ...}; empty when some used run was quiet
     */
    public String busyLabel() {
        return busyOnly() ? "Not one run of this report was made on a machine known to be quiet (" + machineCounts() + "): its run "
                + "times, distances and misses measure the machine's load as much as the periods; re-run on a quiet "
                + "machine to compare sets." : "";
    }

    /** @return the runs per machine verdict in words, e.g. {@code 2 busy, 4 quiet} */
    public String machineCounts() {
        List<String> counts = new ArrayList<>();
        byMachine.forEach((k, n) -> counts.add(n + " " + k));
        return String.join(", ", counts);
    }

    /** @return one paragraph for report.md: the counts, what is used and why */
    public String text() {
        String s = String.format(Locale.ROOT, "Machine during the runs: %d run(s): %s. ", runs, machineCounts());
        int unrecorded = byMachine.getOrDefault(RunMachine.UNRECORDED, 0);
        if (unrecorded > 0) {
            s += unrecorded + " run(s) were made before rtaware recorded the machine's conditions: whether the machine "
                    + "was quiet during them is not known. ";
        }
        s += includeBusy ? "This report uses all " + used + " of them (--include-busy): runs on a busy or unknown machine "
                + "are mixed in."
                : "This report (tables, t-tests, claims, figures) uses the " + used + " quiet run(s) only (" + RULE
                + "); --include-busy uses all.";
        if (otherCpus.n() > 0) {
            s += String.format(Locale.ROOT, " Over the runs used, other processes took %s to %s CPUs (median %s), the load at"
                    + " the start was %s to %s, the longest GC pause of a run %s to %s ms.", n(otherCpus.min()),
                    n(otherCpus.max()), n(otherCpus.median()), n(loadStart.min()), n(loadStart.max()),
                    n(gcMaxPauseMs.min()), n(gcMaxPauseMs.max()));
        }
        if (!leftOut.isEmpty()) {
            s += " Left out: " + String.join("; ", leftOut) + ".";
        }
        return s;
    }

    private static String n(Double v) {
        return v == null ? "n/a" : String.format(Locale.ROOT, "%.2f", v);
    }
}
