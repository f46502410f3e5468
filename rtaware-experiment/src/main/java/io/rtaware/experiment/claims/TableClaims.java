package io.rtaware.experiment.claims;

import static io.rtaware.experiment.claims.Judging.argBest;
import static io.rtaware.experiment.claims.Judging.num;
import static io.rtaware.experiment.claims.Judging.pct;
import static io.rtaware.experiment.claims.Judging.spread;

import io.rtaware.experiment.ExperimentSummary.SetSummary;
import io.rtaware.experiment.PaperReference;
import io.rtaware.experiment.stats.MeanInterval;
import io.rtaware.experiment.stats.WelchTest;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

/**
 * The paper's claims about Tables I and II (Section VII), judged on the sets whose periods are a
 * paper set's at the paper's top speed.
 */
final class TableClaims {

    private TableClaims() {
    }

    /** "The total run times from Sets 1 and 4 were statistically different as well as Sets 1 and 5." */
    static final class Set1Faster extends ClaimFamily {

        Set1Faster() {
            super("table1-set1-faster",
                    "Table I t-tests: the run times of Sets 1 and 4, and of Sets 1 and 5, are statistically different "
                    + "(Set 1 faster)");
        }

        @Override
        public void judge(Judging j) {
            List<int[]> pairs = List.of(new int[] {1, 4}, new int[] {1, 5});
            List<String> parts = new ArrayList<>();
            int agree = 0;
            for (int[] pair : pairs) {
                WelchTest t = j.test(pair[0], pair[1], "run_time_s");
                String missing = j.missing(pair, t);
                if (missing != null) {
                    j.unjudged(this, Scope.PAPER, missing);
                    return;
                }
                double a = j.paper().get(pair[0]).runTimeS().mean();
                double b = j.paper().get(pair[1]).runTimeS().mean();
                agree += t.p() < PaperClaims.ALPHA && a < b ? 1 : 0;
                parts.add("Set " + pair[0] + " vs Set " + pair[1] + ": " + num(a, 2) + " s vs " + num(b, 2) + " s, p = "
                        + num(t.p(), 4));
            }
            j.judged(this, Scope.PAPER, Verdict.ofParts(agree, pairs.size()), String.join("; ", parts)
                    + " (paper: 266.95 s vs 276.97 s and 272.68 s, both statistically different).",
                    "Welch's two-sided t-test on the completed runs; a pair agrees if p < " + PaperClaims.ALPHA
                            + " and Set 1's mean is the lower; reproduced if both agree, not reproduced if neither, mixed "
                            + "otherwise",
                    j.paperSets(1, 4, 5), s -> s.runTimeS().n());
        }
    }

    /** "Sets 2 and 4, Sets 3 and 4, and Sets 4 and 5 had confidence intervals of 82%, 85% and 79%." */
    static final class OnTheVerge extends ClaimFamily {

        OnTheVerge() {
            super("table1-verge",
                    "Table I t-tests: the run times of Sets 2 and 4, 3 and 4, and 4 and 5 are on the verge of significance "
                    + "(confidence 82%, 85%, 79%)");
        }

        @Override
        public void judge(Judging j) {
            List<int[]> pairs = List.of(new int[] {2, 4}, new int[] {3, 4}, new int[] {4, 5});
            List<String> paperConfidence = List.of("82%", "85%", "79%");
            List<String> parts = new ArrayList<>();
            int agree = 0;
            for (int i = 0; i < pairs.size(); i++) {
                int[] pair = pairs.get(i);
                WelchTest t = j.test(pair[0], pair[1], "run_time_s");
                String missing = j.missing(pair, t);
                if (missing != null) {
                    j.unjudged(this, Scope.PAPER, missing);
                    return;
                }
                agree += t.confidence() >= PaperClaims.VERGE_MIN && t.confidence() < PaperClaims.VERGE_MAX ? 1 : 0;
                parts.add("Set " + pair[0] + " vs Set " + pair[1] + ": confidence " + pct(t.confidence()) + " (paper "
                        + paperConfidence.get(i) + ")");
            }
            j.judged(this, Scope.PAPER, Verdict.ofParts(agree, pairs.size()), String.join("; ", parts) + ".",
                    "Welch's two-sided t-test on the completed runs, confidence = 1 - p; a pair agrees if its confidence is "
                            + "at least " + pct(PaperClaims.VERGE_MIN) + " and below " + pct(PaperClaims.VERGE_MAX)
                            + "; reproduced if all three agree, not reproduced if none does, mixed otherwise",
                    j.paperSets(2, 3, 4, 5), s -> s.runTimeS().n());
        }
    }

    /** "The t-test results for distance from the finish show that the data sets were not statistically different." */
    static final class DistancesAlike extends ClaimFamily {

        DistancesAlike() {
            super("table2-no-difference",
                    "Table II t-tests: the distances to the finish of no two sets are statistically different");
        }

        @Override
        public void judge(Judging j) {
            List<String> parts = new ArrayList<>();
            List<String> skipped = new ArrayList<>();
            int different = 0;
            int tested = 0;
            List<Integer> numbers = new ArrayList<>(j.paper().keySet());
            for (int i = 0; i < numbers.size(); i++) {
                for (int k = i + 1; k < numbers.size(); k++) {
                    WelchTest t = j.test(numbers.get(i), numbers.get(k), "distance_to_finish_m");
                    String pair = "Set " + numbers.get(i) + " vs Set " + numbers.get(k);
                    if (t == null || !t.applicable()) {
                        skipped.add(pair);
                        continue;
                    }
                    tested++;
                    if (t.p() < PaperClaims.ALPHA) {
                        different++;
                        parts.add(pair + " p = " + num(t.p(), 4));
                    }
                }
            }
            if (tested == 0) {
                j.unjudged(this, Scope.PAPER, numbers.size() < 2
                        ? "fewer than two of the paper's sets (at the paper's top speed) were run"
                        : "no t-test between the paper's sets is defined (" + String.join(", ", skipped)
                                + ": fewer than two runs, or no variance)");
                return;
            }
            Verdict v = different == 0 ? Verdict.REPRODUCED : different * 2 >= tested ? Verdict.NOT_REPRODUCED
                    : Verdict.MIXED;
            List<String> blind = new ArrayList<>();
            if (v == Verdict.REPRODUCED) {
                for (int i = 0; i < numbers.size(); i++) {
                    for (int k = i + 1; k < numbers.size(); k++) {
                        WelchTest t = j.test(numbers.get(i), numbers.get(k), "distance_to_finish_m");
                        List<PaperReference.PaperSet> published = PaperReference.published().sets();
                        double paperDiff = Math.abs(published.get(numbers.get(i) - 1).distanceMeanM()
                                - published.get(numbers.get(k) - 1).distanceMeanM());
                        if (t != null && t.applicable() && t.detectableDifference() > paperDiff) {
                            blind.add("Set " + numbers.get(i) + " vs Set " + numbers.get(k) + " detects "
                                    + num(t.detectableDifference(), 3) + " m, the paper's difference is "
                                    + num(paperDiff, 3) + " m");
                        }
                    }
                }
                if (!blind.isEmpty()) {
                    v = Verdict.INCONCLUSIVE;
                }
            }
            String evidence = different + " of " + tested + " pairs of the paper's sets (" + j.names(numbers)
                    + ") differ with p < " + PaperClaims.ALPHA + (parts.isEmpty() ? "" : ": " + String.join("; ", parts))
                    + (skipped.isEmpty() ? "" : "; not testable: " + String.join(", ", skipped))
                    + (blind.isEmpty() ? "" : "; too weak to see the paper's differences: " + String.join("; ", blind))
                    + ".";
            j.judged(this, Scope.PAPER, v, evidence, "Welch's two-sided t-test between every pair of the paper's sets "
                    + "present, on every run that ended on the course; reproduced if no pair has p < " + PaperClaims.ALPHA
                    + " and every test could have detected the paper's difference of the two sets' means (the smallest "
                    + "difference detectable at alpha " + WelchTest.ALPHA + " with " + pct(WelchTest.POWER) + " power, from "
                    + "the observed spread and n, is at most the paper's); inconclusive if no pair differs but a test could "
                    + "not have; not reproduced if at least half the pairs differ, mixed otherwise (no correction for "
                    + "multiple tests, like the paper)",
                    j.paperSets(), s -> s.distanceToFinishM().n());
        }
    }

    /** "Although Set 3 has the fastest average run time, it also has the highest standard deviation." */
    static final class Set3FastestWidest extends ClaimFamily {

        Set3FastestWidest() {
            super("table1-set3-fastest-widest",
                    "Table I: Set 3 has the fastest mean run time and the highest standard deviation");
        }

        @Override
        public void judge(Judging j) {
            Map<Integer, SetSummary> paper = j.paper();
            if (paper.size() < 5 || paper.values().stream().anyMatch(s -> s.runTimeS().sd() == null)) {
                j.unjudged(this, Scope.PAPER, "needs all five paper sets with at least two completed runs each; have "
                        + j.paperNames());
                return;
            }
            SetSummary three = paper.get(3);
            Map<Integer, SetSummary> others = new java.util.TreeMap<>(paper);
            others.remove(3);
            // Each part against the other set closest to beating Set 3 at it: the one that binds.
            int rival = argBest(others, s -> -s.runTimeS().mean());
            MeanInterval faster = MeanInterval.meanDifference(three.runTimeS(), paper.get(rival).runTimeS());
            boolean fastest = faster.upper() < 0;
            int wideRival = argBest(others, s -> s.runTimeS().sd());
            MeanInterval wider = MeanInterval.varianceRatio(three.runTimeS(), paper.get(wideRival).runTimeS());
            boolean widest = wider.lower() > 1;
            j.judged(this, Scope.PAPER, Verdict.ofParts((fastest ? 1 : 0) + (widest ? 1 : 0), 2),
                    "fastest: Set 3 " + num(three.runTimeS().mean(), 2) + " s against the fastest other, Set " + rival + " "
                            + num(paper.get(rival).runTimeS().mean(), 2) + " s: difference " + num(faster.estimate(), 2)
                            + " s (95% CI " + num(faster.lower(), 2) + " to " + num(faster.upper(), 2) + ") "
                            + (fastest ? "shown" : "not shown") + "; widest: Set 3 SD " + num(three.runTimeS().sd(), 2)
                            + " s against the widest other, Set " + wideRival + " " + num(paper.get(wideRival).runTimeS().sd(), 2)
                            + " s: variance ratio " + num(wider.estimate(), 2) + " (95% CI " + num(wider.lower(), 2) + " to "
                            + num(wider.upper(), 2) + ") " + (widest ? "shown" : "not shown") + " (paper: Set 3 265.89 +- "
                            + "11.19 s, fastest by 1.06 s, widest by 0.80 s).",
                    "two parts, each against the other paper set that comes closest: 'fastest' is shown if the 95% Welch "
                            + "interval of Set 3's mean run time minus that set's lies below 0, 'widest' if the 95% F interval "
                            + "of the ratio of their run-time variances lies above 1; reproduced if both are shown, not "
                            + "reproduced if neither, mixed if one",
                    j.paperSets(), s -> s.runTimeS().n());
        }
    }

    /** "The run time values and distance from the finish position are almost identical (Tables I - II)." */
    static final class AlmostIdentical extends ClaimFamily {

        AlmostIdentical() {
            super("tables-almost-identical",
                    "Tables I and II: run times and distances to the finish are almost identical across sets");
        }

        @Override
        public void judge(Judging j) {
            Map<Integer, SetSummary> paper = j.paper();
            List<SetSummary> withTimes = paper.values().stream().filter(s -> s.runTimeS().mean() != null).toList();
            List<SetSummary> withDistances = paper.values().stream().filter(s -> s.distanceToFinishM().mean() != null)
                    .toList();
            if (withTimes.size() < 2 || withDistances.size() < 2) {
                j.unjudged(this, Scope.PAPER, "needs at least two of the paper's sets with a mean run time and a mean "
                        + "distance to the finish; have " + withTimes.size() + " and " + withDistances.size());
                return;
            }
            double time = spread(withTimes, s -> s.runTimeS().mean());
            double distance = spread(withDistances, s -> s.distanceToFinishM().mean());
            int agree = (time <= PaperClaims.SAME_RUN_TIME ? 1 : 0) + (distance <= PaperClaims.SAME_DISTANCE ? 1 : 0);
            j.judged(this, Scope.PAPER, Verdict.ofParts(agree, 2), "over " + j.paperNames()
                    + ": the set means of the run time span " + pct(time) + " of their mean, those of the distance to the "
                    + "finish " + pct(distance) + " (paper: 4.2% and 13.6%).", "spread = (largest set mean - smallest) / "
                    + "mean of the set means; reproduced if at most " + pct(PaperClaims.SAME_RUN_TIME) + " for run time and "
                    + "at most " + pct(PaperClaims.SAME_DISTANCE) + " for distance (the paper's own spreads, rounded up), "
                    + "not reproduced if neither, mixed if one",
                    j.paperSets(), s -> Math.min(s.runTimeS().n(), s.distanceToFinishM().n()));
        }
    }

    /** "The standard deviation for Sets 2 and 3 are almost double of Sets 1, 4 and 5." */
    static final class SpreadTwice extends ClaimFamily {

        SpreadTwice() {
            super("table1-spread-twice",
                    "Table I: Sets 2 and 3 have about twice the run-time spread (standard deviation) of Sets 1, 4 and 5");
        }

        @Override
        public void judge(Judging j) {
            Map<Integer, SetSummary> paper = j.paper();
            List<Integer> wide = List.of(2, 3);
            List<Integer> narrow = List.of(1, 4, 5);
            boolean all = Stream.concat(wide.stream(), narrow.stream())
                    .allMatch(n -> paper.containsKey(n) && paper.get(n).runTimeS().sd() != null);
            if (!all) {
                j.unjudged(this, Scope.PAPER, "needs all five paper sets with at least two completed runs each; have "
                        + j.paperNames());
                return;
            }
            double wideSd = wide.stream().mapToDouble(n -> paper.get(n).runTimeS().sd()).average().orElseThrow();
            double narrowSd = narrow.stream().mapToDouble(n -> paper.get(n).runTimeS().sd()).average().orElseThrow();
            double ratio = wideSd / narrowSd;
            Verdict v = ratio >= PaperClaims.SPREAD_RATIO_MIN ? Verdict.REPRODUCED
                    : ratio < PaperClaims.SPREAD_RATIO_NONE ? Verdict.NOT_REPRODUCED : Verdict.MIXED;
            List<PaperReference.PaperSet> published = PaperReference.published().sets();
            double paperWide = wide.stream().mapToDouble(n -> published.get(n - 1).runTimeSdS()).average().orElseThrow();
            double paperNarrow = narrow.stream().mapToDouble(n -> published.get(n - 1).runTimeSdS()).average()
                    .orElseThrow();
            j.judged(this, Scope.PAPER, v, "mean SD of the run time: Sets 2 and 3 " + num(wideSd, 2) + " s, Sets 1, 4 "
                    + "and 5 " + num(narrowSd, 2) + " s, ratio " + num(ratio, 2) + " (paper: " + num(paperWide, 2)
                    + " s and " + num(paperNarrow, 2) + " s, ratio " + num(paperWide / paperNarrow, 2) + ").",
                    "ratio = mean SD of Sets 2 and 3 over mean SD of Sets 1, 4 and 5; reproduced if at least "
                            + PaperClaims.SPREAD_RATIO_MIN + ", not reproduced if below " + PaperClaims.SPREAD_RATIO_NONE
                            + ", mixed between",
                    j.paperSets(), s -> s.runTimeS().n());
        }
    }
}
