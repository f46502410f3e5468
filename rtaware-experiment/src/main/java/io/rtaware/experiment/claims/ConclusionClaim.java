package io.rtaware.experiment.claims;

import static io.rtaware.experiment.claims.Judging.combine;
import static io.rtaware.experiment.claims.Judging.num;

import io.rtaware.experiment.ExperimentSummary.SetSummary;
import io.rtaware.experiment.RunResult;
import io.rtaware.experiment.stats.BlockedComparison;
import io.rtaware.experiment.stats.PairedDifference;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.function.Predicate;
import java.util.function.ToDoubleFunction;
import org.apache.commons.math3.stat.inference.OneWayAnova;

/**
 * The paper's main conclusion, "the results suggest that task timing does affect the overall
 * system performance", judged as a test of whether the sets differ in performance (run time,
 * distance to the finish). Where the sets share world seeds (run j of every set on seed j, a
 * blocked design), the test is the blocked one: the two-way ANOVA without replication and
 * Friedman's test with the seed as block, on the seeds complete in every set, with the paired
 * differences against the first set; where they do not, a one-way ANOVA of independent samples.
 */
final class ConclusionClaim extends ClaimFamily {

    /** Complete blocks needed for the blocked test; with fewer the sets are compared as independent samples. */
    static final int MIN_BLOCKS = 3;

    /** One performance measure: which runs give it and its value. */
    private record Measure(String name, String unit, Predicate<RunResult> gives, ToDoubleFunction<RunResult> value) {
    }

    private static final List<Measure> MEASURES = List.of(
            new Measure("run time", "s", RunResult::completed, RunResult::runTimeS),
            new Measure("distance to the finish", "m", RunResult::measured, RunResult::distanceToFinishM));

    ConclusionClaim() {
        super("conclusion-timing-matters", "Conclusion: the timing of the tasks affects the overall performance of the "
                + "system (run time, distance to the finish)");
    }

    @Override
    public void judge(Judging j) {
        List<Verdict> verdicts = new ArrayList<>();
        List<String> parts = new ArrayList<>();
        List<String> reasons = new ArrayList<>();
        Set<SetSummary> cells = new LinkedHashSet<>();
        int fewest = Integer.MAX_VALUE;
        Map<String, List<SetSummary>> bySpeed = j.bySpeed();
        for (Map.Entry<String, List<SetSummary>> group : bySpeed.entrySet()) {
            String at = bySpeed.size() > 1 ? "at " + group.getKey() + ": " : "";
            List<SetSummary> sets = group.getValue();
            if (sets.size() < 2) {
                reasons.add(at + "one set only");
                continue;
            }
            int significant = 0;
            int partly = 0;
            int tested = 0;
            for (Measure m : MEASURES) {
                List<double[]> samples = new ArrayList<>();
                for (SetSummary s : sets) {
                    samples.add(j.rows().stream().filter(r -> r.set() == s.set() && m.gives().test(r))
                            .mapToDouble(m.value()).filter(Double::isFinite).toArray());
                }
                double[][] blocks = blocks(j, sets, m);
                if (blocks.length >= MIN_BLOCKS) {
                    BlockedComparison c = BlockedComparison.of(blocks);
                    tested++;
                    cells.addAll(sets);
                    fewest = Math.min(fewest, blocks.length);
                    boolean anova = c.anovaP() < PaperClaims.ALPHA;
                    boolean friedman = c.friedmanP() < PaperClaims.ALPHA;
                    significant += anova && friedman ? 1 : 0;
                    partly += anova || friedman ? 1 : 0;
                    parts.add(at + m.name() + ", blocked on the world seed (" + blocks.length + " seeds complete in all "
                            + sets.size() + " sets): two-way ANOVA F(" + c.dfTreatments() + ", " + c.dfError() + ") = "
                            + num(c.f(), 2) + ", p = " + num(c.anovaP(), 4) + "; Friedman chi2 = " + num(c.friedmanChi2(), 2)
                            + ", p = " + num(c.friedmanP(), 4) + "; paired differences against " + sets.get(0).name() + ": "
                            + paired(sets, blocks, m.unit()));
                } else {
                    // The sets with at least two values are compared; a set with fewer (e.g. one whose
                    // runs never completed) is named and left out rather than stopping the test.
                    List<double[]> testable = new ArrayList<>();
                    List<SetSummary> testedSets = new ArrayList<>();
                    List<String> leftOut = new ArrayList<>();
                    for (int i = 0; i < sets.size(); i++) {
                        if (samples.get(i).length >= 2) {
                            testable.add(samples.get(i));
                            testedSets.add(sets.get(i));
                        } else {
                            leftOut.add(sets.get(i).name() + " (" + samples.get(i).length + ")");
                        }
                    }
                    if (testable.size() < 2) {
                        reasons.add(at + m.name() + ": fewer than two sets have two runs that give it");
                        continue;
                    }
                    OneWayAnova anova = new OneWayAnova();
                    double p = anova.anovaPValue(testable);
                    tested++;
                    cells.addAll(testedSets);
                    fewest = Math.min(fewest, testable.stream().mapToInt(x -> x.length).min().orElseThrow());
                    significant += p < PaperClaims.ALPHA ? 1 : 0;
                    partly += p < PaperClaims.ALPHA ? 1 : 0;
                    parts.add(at + m.name() + ", as independent samples (" + (!sharesSeeds(j, sets)
                            ? "the sets share no world seed" : "only " + blocks.length + " seed(s) complete in every set; "
                            + "the shared seeds ignored, with less power than the blocked test") + "): one-way ANOVA F = "
                            + num(anova.anovaFValue(testable), 2) + ", p = " + num(p, 4)
                            + (leftOut.isEmpty() ? "" : "; left out, with fewer than two runs that give it: "
                            + String.join(", ", leftOut)));
                }
            }
            if (tested > 0) {
                verdicts.add(significant > 0 ? Verdict.REPRODUCED : partly > 0 ? Verdict.MIXED : Verdict.NOT_REPRODUCED);
            }
        }
        if (verdicts.isEmpty()) {
            j.unjudged(this, Scope.PAPER, "needs at least two sets of one top speed with two runs each that give a run "
                    + "time or a distance" + (reasons.isEmpty() ? "" : " (" + String.join("; ", reasons) + ")"));
            return;
        }
        int blocksOrRuns = fewest;
        j.judged(this, Scope.PAPER, combine(verdicts), String.join(". ", parts) + "."
                        + (reasons.isEmpty() ? "" : " Not tested: " + String.join("; ", reasons) + "."),
                "does performance differ between the sets? Blocked on the world seed where at least " + MIN_BLOCKS
                        + " seeds are complete in every set (two-way ANOVA without replication and Friedman's test, seed "
                        + "as block; a measure differs if both give p < " + PaperClaims.ALPHA + "), else a one-way ANOVA on the sets "
                        + "with at least two values "
                        + "(p < " + PaperClaims.ALPHA + "); reproduced if run time or distance to the finish differs, "
                        + "mixed if only one blocked test says so, not reproduced if no test does (no correction for the "
                        + "two measures; a difference in either direction counts, the direction is in the paired "
                        + "differences)" + (bySpeed.size() > 1 ? "; judged per top speed, the verdicts combined (mixed if "
                        + "they differ)" : ""), List.copyOf(cells), s -> blocksOrRuns);
    }

    /**
     * @return {@code [block][set]}: the measure of the one run of each set on each world seed that
     *     every set ran once with a value, in seed order
     */
    private static double[][] blocks(Judging j, List<SetSummary> sets, Measure m) {
        Map<Long, double[]> bySeed = new TreeMap<>();
        Map<Long, int[]> counts = new TreeMap<>();
        for (RunResult r : j.rows()) {
            int column = indexOf(sets, r.set());
            if (column < 0) {
                continue;
            }
            long seed = r.worldSeed();
            counts.computeIfAbsent(seed, k -> new int[sets.size()])[column]++;
            double v = m.gives().test(r) ? m.value().applyAsDouble(r) : Double.NaN;
            bySeed.computeIfAbsent(seed, k -> new double[sets.size()])[column] = v;
        }
        return bySeed.entrySet().stream()
                .filter(e -> java.util.Arrays.stream(counts.get(e.getKey())).allMatch(c -> c == 1)
                        && java.util.Arrays.stream(e.getValue()).allMatch(Double::isFinite))
                .map(Map.Entry::getValue).toArray(double[][]::new);
    }

    /** @return true if some world seed was run in more than one of the sets */
    private static boolean sharesSeeds(Judging j, List<SetSummary> sets) {
        Map<Long, java.util.Set<Integer>> setsBySeed = new TreeMap<>();
        j.rows().stream().filter(r -> indexOf(sets, r.set()) >= 0)
                .forEach(r -> setsBySeed.computeIfAbsent(r.worldSeed(), k -> new java.util.HashSet<>()).add(r.set()));
        return setsBySeed.values().stream().anyMatch(s -> s.size() > 1);
    }

    private static int indexOf(List<SetSummary> sets, int set) {
        for (int i = 0; i < sets.size(); i++) {
            if (sets.get(i).set() == set) {
                return i;
            }
        }
        return -1;
    }

    /** @return e.g. {@code Set 2 -0.36 s (95% CI -1.20 to 0.48)} for every set but the first */
    private static String paired(List<SetSummary> sets, double[][] blocks, String unit) {
        List<String> out = new ArrayList<>();
        double[] first = java.util.Arrays.stream(blocks).mapToDouble(b -> b[0]).toArray();
        for (int k = 1; k < sets.size(); k++) {
            int column = k;
            PairedDifference d = PairedDifference.of(java.util.Arrays.stream(blocks).mapToDouble(b -> b[column]).toArray(),
                    first);
            out.add(sets.get(k).name() + " " + (d.mean() >= 0 ? "+" : "") + num(d.mean(), 2) + " " + unit + " (95% CI "
                    + num(d.lower(), 2) + " to " + num(d.upper(), 2) + ")");
        }
        return String.join(", ", out);
    }
}
