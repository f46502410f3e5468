package io.rtaware.experiment.claims;

import static io.rtaware.experiment.claims.Judging.argBest;
import static io.rtaware.experiment.claims.Judging.num;
import static io.rtaware.experiment.claims.Judging.onAxis;

import io.rtaware.experiment.ExperimentSummary;
import io.rtaware.experiment.ExperimentSummary.SetSummary;
import io.rtaware.experiment.PeriodSet;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Collectors;
import org.apache.commons.math3.stat.correlation.SpearmansCorrelation;

/** The paper's claims about missed deadlines (Figs. 7 and 8, Section VII). */
final class MissClaims {

    /** The order of Fig. 7's claim: most misses first. */
    static final List<String> FIG7_ORDER = List.of("planner", "occupancy", "waypoint", "obstacle");

    private MissClaims() {
    }

    /** "As the individual tasks' periods increase, the tasks' missed deadline rate decreases" (Figs. 7, 8). */
    static final class MissesFall extends ClaimFamily {

        MissesFall() {
            super("misses-fall",
                    "misses fall as periods grow");
        }

        @Override
        public void judge(Judging j) {
            Map<String, List<double[]>> series = new LinkedHashMap<>();
            for (String task : PeriodSet.TASKS) {
                List<double[]> points = new ArrayList<>();
                for (SetSummary s : j.sets()) {
                    Double pct = s.misses().get(task).missPct();
                    if (pct != null) {
                        points.add(new double[] {s.periodsMs().get(task), pct});
                    }
                }
                series.put(task, points);
            }
            List<double[]> all = new ArrayList<>();
            for (SetSummary s : onAxis(j.sets())) {
                Double pct = s.misses().get(ExperimentSummary.ALL_TASKS).missPct();
                if (pct != null) {
                    all.add(new double[] {s.sweptPeriodMs(), pct});
                }
            }
            series.put("all four (against the swept period)", all);
            series.values().removeIf(points -> points.stream().mapToDouble(p -> p[0]).distinct().count()
                    < PaperClaims.MIN_PERIODS);
            if (series.isEmpty()) {
                j.unjudged(this, Scope.PAPER, "no task's period takes " + PaperClaims.MIN_PERIODS
                        + " or more values across the sets");
                return;
            }
            List<String> parts = new ArrayList<>();
            int falls = 0;
            for (Map.Entry<String, List<double[]>> e : series.entrySet()) {
                double[] x = e.getValue().stream().mapToDouble(p -> p[0]).toArray();
                double[] y = e.getValue().stream().mapToDouble(p -> p[1]).toArray();
                double rho = new SpearmansCorrelation().correlation(x, y);
                boolean fall = rho <= PaperClaims.FALLS_RHO;
                falls += fall ? 1 : 0;
                double[] first = e.getValue().stream().min(Comparator.comparingDouble(p -> p[0])).orElseThrow();
                double[] last = e.getValue().stream().max(Comparator.comparingDouble(p -> p[0])).orElseThrow();
                parts.add(e.getKey() + ": rho " + (Double.isNaN(rho) ? "undefined (the same miss % everywhere)"
                        : num(rho, 2)) + " over " + x.length + " sets, " + num(first[1], 2) + "% at " + (long) first[0]
                        + " ms, " + num(last[1], 2) + "% at " + (long) last[0] + " ms");
            }
            j.judged(this, Scope.PAPER, Verdict.ofParts(falls, series.size()), String.join("; ", parts) + ".",
                    "for each task whose period takes at least " + PaperClaims.MIN_PERIODS + " values across the sets (its "
                            + "miss % against its period), and for all four tasks against the swept period: Spearman's rank "
                            + "correlation rho; a series falls if rho <= " + PaperClaims.FALLS_RHO + "; reproduced if every "
                            + "series falls, not reproduced if none does, mixed otherwise",
                    j.sets().stream().filter(s -> s.measuredRuns() > 0).toList(), SetSummary::measuredRuns);
        }
    }

    /** "In Sets 1, 4 and 5, the tasks with the highest missed deadline rate are the planner followed by ..." (Fig. 7). */
    static final class Fig7PlannerMost extends ClaimFamily {

        Fig7PlannerMost() {
            super("fig7-planner-most",
                    "Fig. 7: in Sets 1, 4 and 5 the planner misses most, then occupancy, waypoint and obstacle");
        }

        @Override
        public void judge(Judging j) {
            List<String> parts = new ArrayList<>();
            int agree = 0;
            int judged = 0;
            for (int n : List.of(1, 4, 5)) {
                SetSummary s = j.paper().get(n);
                if (s == null || FIG7_ORDER.stream().anyMatch(t -> s.misses().get(t).missPct() == null)) {
                    continue;
                }
                judged++;
                List<String> order = FIG7_ORDER.stream()
                        .sorted(Comparator.comparingDouble((String t) -> s.misses().get(t).missPct()).reversed()).toList();
                boolean strict = true;
                for (int i = 1; i < FIG7_ORDER.size(); i++) {
                    strict &= s.misses().get(FIG7_ORDER.get(i - 1)).missPct() > s.misses().get(FIG7_ORDER.get(i)).missPct();
                }
                agree += strict ? 1 : 0;
                List<String> ranked = new ArrayList<>();
                order.forEach(t -> ranked.add(t + " " + num(s.misses().get(t).missPct(), 2) + "%"));
                parts.add("Set " + n + ": " + String.join(" > ", ranked));
            }
            if (judged == 0) {
                j.unjudged(this, Scope.PAPER, "none of the paper's Sets 1, 4 and 5 (at the paper's top speed) was run");
                return;
            }
            j.judged(this, Scope.PAPER, Verdict.ofParts(agree, judged), String.join("; ", parts) + ".",
                    "a set agrees if its miss % is strictly ordered planner > occupancy > waypoint > obstacle; reproduced if "
                            + "every one of Sets 1, 4 and 5 present agrees, not reproduced if none does, mixed otherwise",
                    j.paperSets(1, 4, 5), SetSummary::measuredRuns);
        }
    }

    /** "Figure 8 shows ... the overall missed deadline rate decreases": Set 1 highest. */
    static final class Fig8Set1MostMisses extends ClaimFamily {

        Fig8Set1MostMisses() {
            super("fig8-set1-most-misses",
                    "Fig. 8: Set 1 (all tasks at 10 ms) has the highest share of missed deadlines");
        }

        @Override
        public void judge(Judging j) {
            Map<Integer, SetSummary> paper = j.paper();
            List<SetSummary> withMisses = paper.values().stream()
                    .filter(s -> s.misses().get(ExperimentSummary.ALL_TASKS).missPct() != null).toList();
            if (!paper.containsKey(1) || withMisses.size() < 2 || !withMisses.contains(paper.get(1))) {
                j.unjudged(this, Scope.PAPER, "needs the paper's Set 1 and another paper set with misses counted; have "
                        + j.paperNames());
                return;
            }
            int highest = argBest(paper.entrySet().stream().filter(e -> withMisses.contains(e.getValue()))
                    .collect(Collectors.toMap(Map.Entry::getKey, Map.Entry::getValue, (a, b) -> a, TreeMap::new)),
                    s -> s.misses().get(ExperimentSummary.ALL_TASKS).missPct());
            List<String> parts = new ArrayList<>();
            paper.forEach((n, s) -> parts.add("Set " + n + " " + num(s.misses().get(ExperimentSummary.ALL_TASKS).missPct(), 2)
                    + "%"));
            j.judged(this, Scope.PAPER, highest == 1 ? Verdict.REPRODUCED : Verdict.NOT_REPRODUCED,
                    "misses of all four tasks' releases: " + String.join(", ", parts) + "; highest: Set " + highest + ".",
                    "reproduced if Set 1 has the highest miss % of the paper's sets present, not reproduced otherwise",
                    withMisses, SetSummary::measuredRuns);
        }
    }

    /** "It is shown that Set 1's individual tasks had the highest percentage of missed deadlines" (Fig. 7). */
    static final class Fig7Set1HighestPerTask extends ClaimFamily {

        Fig7Set1HighestPerTask() {
            super("fig7-set1-highest-per-task",
                    "Fig. 7: Set 1 has the highest miss rate of every task");
        }

        @Override
        public void judge(Judging j) {
            SetSummary one = j.paper().get(1);
            List<SetSummary> others = j.paperSets().stream().filter(s -> s != one).toList();
            if (one == null || others.isEmpty()) {
                j.unjudged(this, Scope.PAPER, "needs the paper's Set 1 and another paper set; have " + j.paperNames());
                return;
            }
            List<String> parts = new ArrayList<>();
            int agree = 0;
            int judged = 0;
            for (String task : PeriodSet.TASKS) {
                Double mine = one.misses().get(task).missPct();
                SetSummary top = others.stream().filter(s -> s.misses().get(task).missPct() != null)
                        .max(Comparator.comparingDouble(s -> s.misses().get(task).missPct())).orElse(null);
                if (mine == null || top == null) {
                    continue;
                }
                judged++;
                double theirs = top.misses().get(task).missPct();
                agree += mine > theirs ? 1 : 0;
                parts.add(task + ": Set 1 " + num(mine, 2) + "%, highest of the others " + top.name() + " "
                        + num(theirs, 2) + "%");
            }
            if (judged == 0) {
                j.unjudged(this, Scope.PAPER, "no task has misses counted in Set 1 and another paper set");
                return;
            }
            j.judged(this, Scope.PAPER, Verdict.ofParts(agree, judged), String.join("; ", parts) + ".",
                    "a task agrees if Set 1's miss % is above that of every other paper set present; reproduced if every "
                            + "task agrees, not reproduced if none does, mixed otherwise",
                    j.paperSets(), SetSummary::measuredRuns);
        }
    }

    /**
     * "The computational requirements of the tasks follow in that order": planner, occupancy,
     * waypoint, obstacle. The requirement is read from the execution time the runs measured.
     */
    static final class ComputationOrder extends ClaimFamily {

        ComputationOrder() {
            super("computation-order",
                    "Section VII: the computational requirements of the tasks follow Fig. 7's order: planner, occupancy, "
                    + "waypoint, obstacle");
        }

        @Override
        public void judge(Judging j) {
            List<SetSummary> measured = j.sets().stream()
                    .filter(s -> FIG7_ORDER.stream().allMatch(t -> s.misses().get(t).execP99UsMean() != null)).toList();
            if (measured.isEmpty()) {
                j.unjudged(this, Scope.PAPER, "no set has the execution time of all four tasks");
                return;
            }
            List<String> parts = new ArrayList<>();
            int agree = 0;
            for (SetSummary s : measured) {
                List<String> order = FIG7_ORDER.stream().sorted(Comparator.comparingDouble(
                        (String t) -> s.misses().get(t).execP99UsMean()).reversed()).toList();
                boolean strict = true;
                for (int i = 1; i < FIG7_ORDER.size(); i++) {
                    strict &= s.misses().get(FIG7_ORDER.get(i - 1)).execP99UsMean()
                            > s.misses().get(FIG7_ORDER.get(i)).execP99UsMean();
                }
                agree += strict ? 1 : 0;
                parts.add(s.name() + ": " + String.join(" > ", order.stream()
                        .map(t -> t + " " + num(s.misses().get(t).execP99UsMean(), 0) + " us").toList()));
            }
            j.judged(this, Scope.PAPER, Verdict.ofParts(agree, measured.size()), String.join("; ", parts) + ".",
                    "the computation of a task is its p99 execution time per run (the execution-time figure results.csv "
                            + "keeps), averaged over the set's runs; a set agrees if it orders the tasks strictly planner > "
                            + "occupancy > waypoint > obstacle; reproduced if every set agrees, not reproduced if none "
                            + "does, mixed otherwise", measured, SetSummary::measuredRuns);
        }
    }
}
