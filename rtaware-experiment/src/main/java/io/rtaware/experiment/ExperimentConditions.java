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
 * @param leftOut each run left out, with the reason
 * @param otherCpus CPU used by other processes during the used runs, CPUs
 * @param stealPct steal during the used runs, percent
 * @param loadStart the load average at the start of the used runs
 * @param gcMaxPauseMs the longest GC pause of each used run, ms
 * @param timeToSafepointMaxMs the longest time to safepoint of each used run, ms
 * @param waitedForQuietS the time waited for a quiet machine before each used run, s
 */
public record ExperimentConditions(boolean includeBusy, String rule, int runs, Map<String, Integer> byMachine, int used,
                                   List<String> leftOut, Spread otherCpus, Spread stealPct, Spread loadStart,
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
        return new ExperimentConditions(includeBusy, RULE, rows.size(), byMachine, used.size(), leftOut,
                Spread.of(used, RunMachine::otherCpus), Spread.of(used, RunMachine::stealPct),
                Spread.of(used, RunMachine::loadStart), Spread.of(used, RunMachine::gcMaxPauseMs),
                Spread.of(used, RunMachine::timeToSafepointMaxMs),
                Spread.of(used.stream().filter(r -> !RunMachine.UNRECORDED.equals(r.machine().machine())).toList(),
                        RunMachine::waitedS));
    }

    /** @return one paragraph for report.md: the counts, what is used and why */
    public String text() {
        List<String> counts = new ArrayList<>();
        byMachine.forEach((k, n) -> counts.add(n + " " + k));
        String s = String.format(Locale.ROOT, "Machine during the runs: %d run(s): %s. ", runs, String.join(", ", counts));
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
