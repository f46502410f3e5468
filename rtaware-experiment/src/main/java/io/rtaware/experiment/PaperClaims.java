package io.rtaware.experiment;

import com.fasterxml.jackson.annotation.JsonValue;
import io.rtaware.experiment.ExperimentSummary.Misses;
import io.rtaware.experiment.ExperimentSummary.PairTest;
import io.rtaware.experiment.ExperimentSummary.SetSummary;
import io.rtaware.experiment.stats.RateInterval;
import io.rtaware.experiment.stats.WelchTest;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.TreeMap;
import java.util.function.Function;
import org.apache.commons.math3.stat.correlation.SpearmansCorrelation;

/**
 * The paper's claims, each given a verdict computed from an experiment's results by an
 * explicit rule (stated with each verdict and in the report), never set by hand. A claim whose
 * data the experiment does not have (no set above 100 ms, no paper Set 4, no variance for a
 * t-test) is not given a verdict but listed as not evaluated, with the reason.
 *
 * <p>The period of a set, for the claims about periods, is {@link SetSummary#sweptPeriodMs()}:
 * the period its swept tasks share. Claims about too-slow and too-fast periods are judged per
 * top speed when the sets differ in speed. Tables I and II and Fig. 7 are judged on the sets
 * whose periods are those of a paper set and whose top speed is the paper's (or {@code run}'s
 * default).
 */
public final class PaperClaims {

    /** A verdict on a claim. */
    public enum Verdict {
        /** The results show what the paper claims. */
        REPRODUCED,
        /** The results do not show it. */
        NOT_REPRODUCED,
        /** The results show it in part. */
        MIXED,
        /** The results show no difference, but the test could not have detected the paper's difference. */
        INCONCLUSIVE,
        /** The setup cannot reproduce the claim's mechanism (the evidence says why). */
        NOT_COMPARABLE;

        /**
         * @return the name in {@code summary.json}: {@code reproduced}, {@code not_reproduced},
         *     {@code mixed}, {@code inconclusive} or {@code not_comparable}
         */
        @JsonValue
        public String json() {
            return name().toLowerCase(Locale.ROOT);
        }
    }

    /**
     * One claim with its verdict.
     *
     * @param id the claim's stable id, e.g. {@code table1-set1-faster} or {@code slow-hits@0.5mps},
     *     by which docs quote its verdict ({@code claim `FOLDER/ID`: VERDICT})
     * @param claim what the paper says (with the course and top speed it was judged on, when
     *     they are not the paper's)
     * @param verdict what the results say
     * @param evidence the numbers the verdict rests on
     * @param rule how the verdict follows from the numbers
     */
    public record Claim(String id, String claim, Verdict verdict, String evidence, String rule) {
    }

    /**
     * A claim these results cannot decide.
     *
     * @param id the claim's stable id, as {@link Claim#id()}
     * @param claim what the paper says
     * @param reason which data is missing
     */
    public record NotEvaluated(String id, String claim, String reason) {
    }

    /** Each claim's id on the paper's course at the paper's top speed, by its text. */
    private static final Map<String, String> IDS = new LinkedHashMap<>();

    /**
     * What a claim is judged on besides the paper's own course and top speed, in the claim's
     * words and in its id: {@code " on office"} and {@code "-on-office"}, {@code " (at 0.5 m/s)"}
     * and {@code "@0.5mps"}. The id is made here, with the words, and never read back from them: a
     * course named by a path ({@code /data/courses/hall.yaml}) has its file's base name in the id.
     */
    private record Scope(String words, String idSuffix) {

        static final Scope PAPER = new Scope("", "");

        /** @return this scope on a course: unchanged on the paper's room (or when none is named) */
        Scope on(String scenario) {
            if (scenario == null || PAPER_COURSE.equals(scenario)) {
                return this;
            }
            String base = scenario.substring(Math.max(scenario.lastIndexOf('/'), scenario.lastIndexOf('\\')) + 1)
                    .replaceFirst("\\.(ya?ml)$", "").replaceAll("[^A-Za-z0-9._-]", "-");
            return new Scope(words + " on " + scenario, idSuffix + "-on-" + (base.isEmpty() ? "course" : base));
        }

        /** @return this scope at one top speed, named as in {@code "0.5 m/s"} */
        Scope at(String speed) {
            return new Scope(words + " (at " + speed + ")", idSuffix + "@" + speed.replace(" m/s", "mps")
                    .replace("run's default top speed", "default").replace(' ', '-'));
        }
    }

    /**
     * @param claims the claims with a verdict
     * @param notEvaluated the claims without one
     */
    public record Verdicts(List<Claim> claims, List<NotEvaluated> notEvaluated) {
    }

    /** Periods above this are "too slow" in the paper's claim, ms. */
    public static final long SLOW_ABOVE_MS = 100;
    /** Periods at or below this are "too fast" in the paper's claim, ms. */
    public static final long FAST_AT_MOST_MS = 5;
    /** Share of runs that makes an effect the rule for a set ("at least half its runs"). */
    public static final double MAJORITY = 0.5;
    /** Spearman's rank correlation at or below which misses "fall" as periods grow. */
    public static final double FALLS_RHO = -0.7;
    /** Distinct periods a series needs before a trend is read from it. */
    public static final int MIN_PERIODS = 3;
    /** Significance level of the t-tests, as the paper's "statistically different". */
    public static final double ALPHA = 0.05;
    /** Confidence range (1 - p) read as "on the verge of significance", from the paper's 79-85%. */
    public static final double VERGE_MIN = 0.75;
    /** Upper end of that range: at or above it a difference is significant, not on the verge. */
    public static final double VERGE_MAX = 1 - ALPHA;
    /** Largest spread of the set means, over their mean, for run times to be "almost identical" (paper: 4.2%). */
    public static final double SAME_RUN_TIME = 0.05;
    /** The same for distances to the finish (paper: 13.6%). */
    public static final double SAME_DISTANCE = 0.15;

    static final String SLOW = "periods above 100 ms: the robot hits walls and obstacles";
    static final String RULE = "the reaction rule: collisions begin near its largest safe period";
    private static final String PAPER_COURSE = "paper-room";
    /** The rule's bound counts as near when the first period with a collision is at most this many times it. */
    public static final double RULE_NEAR = 2.0;
    static final String FAST = "periods of 5 ms or less: the system locks up";
    static final String MISSES_FALL = "misses fall as periods grow";
    static final String T_SET1 = "Table I t-tests: the run times of Sets 1 and 4, and of Sets 1 and 5, are statistically "
            + "different (Set 1 faster)";
    static final String T_VERGE = "Table I t-tests: the run times of Sets 2 and 4, 3 and 4, and 4 and 5 are on the verge "
            + "of significance (confidence 82%, 85%, 79%)";
    static final String T_DISTANCE = "Table II t-tests: the distances to the finish of no two sets are statistically different";
    static final String SET3 = "Table I: Set 3 has the fastest mean run time and the highest standard deviation";
    static final String SAME = "Tables I and II: run times and distances to the finish are almost identical across sets";
    static final String FIG7 = "Fig. 7: in Sets 1, 4 and 5 the planner misses most, then occupancy, waypoint and obstacle";

    static final String LOCK_UP_MECHANISM = "The paper's lock-up came from a 1.66 GHz machine starved by the "
            + "controller and the Player server sharing it; here the simulator is light and rtaware skips the releases "
            + "it cannot make, so the mechanism cannot be reproduced and no lock-up says nothing against the paper.";
    static final String SET1_MISSES = "Fig. 8: Set 1 (all tasks at 10 ms) has the highest share of missed deadlines";
    static final String SPREAD = "Table I: Sets 2 and 3 have about twice the run-time spread (standard deviation) of "
            + "Sets 1, 4 and 5";
    static final String CONCLUSION = "Conclusion: the timing of the tasks affects the overall performance of the system";
    static final String AVOIDER_FAST = "An obstacle avoider run too fast hits obstacles";
    static final String SAMPLING = "Advice: sample an input at least twice as fast as it changes (sampling-rate advice)";
    /** Ratio of the mean SD of Sets 2 and 3 to that of Sets 1, 4, 5 from which the spread claim holds. */
    public static final double SPREAD_RATIO_MIN = 1.5;
    /** Ratio below which it does not hold at all. */
    public static final double SPREAD_RATIO_NONE = 1.25;

    static {
        IDS.put(SLOW, "slow-hits");
        IDS.put(FAST, "fast-locks-up");
        IDS.put(MISSES_FALL, "misses-fall");
        IDS.put(T_SET1, "table1-set1-faster");
        IDS.put(T_VERGE, "table1-verge");
        IDS.put(T_DISTANCE, "table2-no-difference");
        IDS.put(SET3, "table1-set3-fastest-widest");
        IDS.put(SAME, "tables-almost-identical");
        IDS.put(FIG7, "fig7-planner-most");
        IDS.put(SET1_MISSES, "fig8-set1-most-misses");
        IDS.put(SPREAD, "table1-spread-twice");
        IDS.put(CONCLUSION, "conclusion-timing-matters");
        IDS.put(AVOIDER_FAST, "avoider-too-fast-hits");
        IDS.put(SAMPLING, "sampling-rate-advice");
        IDS.put(RULE, "reaction-rule-bound");
    }

    private static final List<String> FIG7_ORDER = List.of("planner", "occupancy", "waypoint", "obstacle");

    private final List<SetSummary> sets;
    private final Map<String, List<PairTest>> tests;
    private final List<Claim> claims = new ArrayList<>();
    private final List<NotEvaluated> notEvaluated = new ArrayList<>();

    private PaperClaims(List<SetSummary> sets, Map<String, List<PairTest>> tests) {
        this.sets = sets;
        this.tests = tests;
    }

    private void judged(String text, Scope scope, Verdict verdict, String evidence, String rule) {
        claims.add(new Claim(Objects.requireNonNull(IDS.get(text), text) + scope.idSuffix(), text + scope.words(), verdict, evidence, rule));
    }

    private void unjudged(String text, Scope scope, String reason) {
        notEvaluated.add(new NotEvaluated(Objects.requireNonNull(IDS.get(text), text) + scope.idSuffix(), text + scope.words(), reason));
    }

    /**
     * @param sets the experiment's sets, summarized
     * @param tests its Welch tests per quantity
     * @return the verdicts, in a fixed order of claims
     */
    public static Verdicts evaluate(List<SetSummary> sets, Map<String, List<PairTest>> tests) {
        return evaluate(sets, tests, null);
    }

    /**
     * @param sets the experiment's sets, summarized
     * @param tests its Welch tests per quantity
     * @param scenario the experiment's scenario, named in the claims that depend on the course
     *     (the collision claim and the reaction rule's) unless it is the paper's room, or null
     * @return the verdicts, in a fixed order of claims
     */
    public static Verdicts evaluate(List<SetSummary> sets, Map<String, List<PairTest>> tests, String scenario) {
        PaperClaims c = new PaperClaims(sets, tests);
        Map<String, List<SetSummary>> bySpeed = new LinkedHashMap<>();
        sets.forEach(s -> bySpeed.computeIfAbsent(speedLabel(s.topSpeedMps()), k -> new ArrayList<>()).add(s));
        // The paper's claims keep their names on the paper's course; another course is named in them.
        Scope course = Scope.PAPER.on(scenario);
        boolean perSpeed = bySpeed.size() > 1;
        bySpeed.forEach((speed, group) -> c.slow(group, perSpeed ? course.at(speed) : course));
        bySpeed.forEach((speed, group) -> c.rule(group, perSpeed ? course.at(speed) : course));
        bySpeed.forEach((speed, group) -> c.fast(group, perSpeed ? Scope.PAPER.at(speed) : Scope.PAPER));
        c.missesFall();
        Map<Integer, SetSummary> paper = c.paperSets();
        c.setOneDiffers(paper);
        c.onTheVerge(paper);
        c.distancesAlike(paper);
        c.setThree(paper);
        c.almostIdentical(paper);
        c.fig7(paper);
        c.setOneMisses(paper);
        c.spreadTwice(paper);
        c.unjudged(CONCLUSION, Scope.PAPER, "a conclusion drawn from the claims above, not a measurement of "
                + "its own: read it from the t-tests of Table I and II and the miss claims");
        c.unjudged(AVOIDER_FAST, Scope.PAPER, "the paper sets change every period at once; an avoider-only "
                + "period sweep with collisions counted per period is the claim 'periods above 100 ms' and the sweep-obstacle "
                + "folder, and a too-fast avoider has no rule here");
        c.unjudged(SAMPLING, Scope.PAPER, "advice, not a measurement: every run's report.json applies it as "
                + "the period advice's sampling bound");
        return new Verdicts(List.copyOf(c.claims), List.copyOf(c.notEvaluated));
    }

    private void slow(List<SetSummary> group, Scope scope) {
        List<SetSummary> above = onAxis(group).stream().filter(s -> s.sweptPeriodMs() > SLOW_ABOVE_MS && s.measuredRuns() > 0)
                .toList();
        if (above.isEmpty()) {
            unjudged(SLOW, scope, "no set with a period above " + SLOW_ABOVE_MS
                    + " ms and a run that ended on the course" + periodsHere(group));
            return;
        }
        List<SetSummary> below = onAxis(group).stream().filter(s -> s.sweptPeriodMs() <= SLOW_ABOVE_MS).toList();
        int belowRuns = below.stream().mapToInt(SetSummary::measuredRuns).sum();
        int belowHits = below.stream().mapToInt(SetSummary::runsWithCollisions).sum();
        boolean baselineClean = belowRuns == 0 || (double) belowHits / belowRuns < MAJORITY;
        boolean allMost = above.stream().allMatch(s -> s.collisionRate() >= MAJORITY);
        boolean none = above.stream().allMatch(s -> s.runsWithCollisions() == 0);
        Verdict v = allMost && baselineClean ? Verdict.REPRODUCED : none ? Verdict.NOT_REPRODUCED : Verdict.MIXED;
        List<String> parts = new ArrayList<>();
        for (SetSummary s : above) {
            parts.add(s.name() + " (" + s.sweptPeriodMs() + " ms): " + s.collisions95().text() + " runs collided ("
                    + s.collisions() + " collisions), " + s.completed() + " of " + s.runs() + " completed"
                    + (s.nearMisses() == null ? "" : ", " + s.runsWithNearMisses() + " with a near miss"));
        }
        String evidence = String.join("; ", parts) + ". At or below " + SLOW_ABOVE_MS + " ms: "
                + (belowRuns == 0 ? "no runs" : RateInterval.of(belowHits, belowRuns).text() + " runs collided") + ". "
                + firstCollision(group) + reactionBound(group);
        judged(SLOW, scope, v, evidence, "reproduced if every set above " + SLOW_ABOVE_MS
                + " ms has a collision in at least " + pct(MAJORITY) + " of its runs and the sets at or below "
                + SLOW_ABOVE_MS + " ms (if any) in fewer than " + pct(MAJORITY) + "; not reproduced if no run above "
                + SLOW_ABOVE_MS + " ms collided; mixed otherwise");
    }

    /**
     * The reaction rule judged by the runs: its largest safe period (mean of the runs' advice)
     * against the shortest swept period at which a run collided.
     */
    private void rule(List<SetSummary> group, Scope scope) {
        Double bound = ruleBound(group);
        List<SetSummary> axis = onAxis(group).stream().filter(s -> s.measuredRuns() > 0).toList();
        if (bound == null || axis.size() < 2) {
            unjudged(RULE, scope, bound == null ? "no run reports the reaction rule's largest safe period"
                    : "fewer than two swept periods with runs on the course" + periodsHere(group));
            return;
        }
        var first = axis.stream().filter(s -> s.runsWithCollisions() > 0).min(Comparator.comparingLong(SetSummary::sweptPeriodMs));
        long longest = axis.stream().mapToLong(SetSummary::sweptPeriodMs).max().orElseThrow();
        if (bound <= 0) {
            noSafePeriod(scope, axis, first);
            return;
        }
        if (first.isEmpty() && longest < bound) {
            unjudged(RULE, scope, "no swept period reaches the rule's largest safe period ("
                    + num(bound, 1) + " ms; the longest is " + longest + " ms) and no run collided: the runs agree with "
                    + "the rule without testing it");
            return;
        }
        Verdict v;
        String evidence;
        if (first.isEmpty()) {
            v = longest > RULE_NEAR * bound ? Verdict.NOT_REPRODUCED : Verdict.MIXED;
            evidence = "largest safe period " + num(bound, 1) + " ms; no run collided up to " + longest + " ms ("
                    + num(longest / bound, 2) + " x the bound)";
        } else {
            double ratio = first.get().sweptPeriodMs() / bound;
            v = ratio < 1 ? Verdict.NOT_REPRODUCED : ratio <= RULE_NEAR ? Verdict.REPRODUCED : Verdict.MIXED;
            evidence = "largest safe period " + num(bound, 1) + " ms; the shortest period with a collision is "
                    + first.get().sweptPeriodMs() + " ms (" + first.get().name() + ", " + first.get().runsWithCollisions()
                    + " of " + first.get().measuredRuns() + " runs), " + num(ratio, 2) + " x the bound";
        }
        judged(RULE, scope, v, evidence + ".", "reproduced if the shortest swept period at which a run collided "
                + "lies between the bound and " + num(RULE_NEAR, 1) + " x the bound; not reproduced if runs collided below "
                + "the bound (the rule is unsafe) or none collided up to beyond " + num(RULE_NEAR, 1) + " x it (the rule is "
                + "far too cautious); mixed otherwise");
    }

    /**
     * The reaction rule found no safe period (its bound is 0 in every run that gave one): it
     * predicts collisions from the shortest period on.
     */
    private void noSafePeriod(Scope scope, List<SetSummary> axis, Optional<SetSummary> first) {
        SetSummary shortest = axis.stream().min(Comparator.comparingLong(SetSummary::sweptPeriodMs)).orElseThrow();
        Verdict v = first.isEmpty() ? Verdict.NOT_REPRODUCED
                : first.get() == shortest ? Verdict.REPRODUCED : Verdict.MIXED;
        List<String> parts = new ArrayList<>();
        for (SetSummary s : axis) {
            parts.add(s.sweptPeriodMs() + " ms " + s.collisions95().text());
        }
        judged(RULE, scope, v, "the rule finds no safe period (the input's age and the stopping distance alone "
                + "use up the avoider's range); runs with a collision: " + String.join("; ", parts) + ".",
                "where the rule finds no safe period: reproduced if runs collided already at the shortest swept period; "
                        + "not reproduced if no run collided at any period; mixed otherwise");
    }

    /** The reaction rule's largest safe period for one task: the mean over the sets whose runs' advice gave it. */
    private record Bound(String task, double ms, int sets) {
    }

    private static Optional<Bound> bound(List<SetSummary> group) {
        for (String task : PeriodSet.TASKS) {
            double[] bounds = group.stream().map(s -> s.misses().get(task).maxSafePeriodMsMean()).filter(Objects::nonNull)
                    .mapToDouble(Double::doubleValue).toArray();
            if (bounds.length > 0) {
                return Optional.of(new Bound(task, java.util.Arrays.stream(bounds).average().orElseThrow(), bounds.length));
            }
        }
        return Optional.empty();
    }

    private static Double ruleBound(List<SetSummary> group) {
        return bound(group).map(Bound::ms).orElse(null);
    }

    /**
     * @param sets sets of one top speed
     * @return the largest safe period the runs' advice gave by the reaction rule (the mean over the
     *     sets that report it), ms, or null when no run reports one
     */
    public static Double reactionRuleBoundMs(List<SetSummary> sets) {
        return ruleBound(sets);
    }

    private static String firstCollision(List<SetSummary> group) {
        return onAxis(group).stream().filter(s -> s.runsWithCollisions() > 0)
                .min(Comparator.comparingLong(SetSummary::sweptPeriodMs))
                .map(s -> "Shortest period with a collision: " + s.sweptPeriodMs() + " ms (" + s.name() + ").")
                .orElse("No run collided at any period.");
    }

    /**
     * @param group the sets of one top speed
     * @return how the shortest period with a collision compares with the largest safe period the
     *     runs' advice gave by the reaction rule, or "" when no run reports that bound
     */
    static String reactionBound(List<SetSummary> group) {
        Optional<Bound> found = bound(group);
        if (found.isEmpty()) {
            return "";
        }
        Bound b = found.get();
        if (b.ms() <= 0) {
            return " Reaction rule (the runs' advice): no period of " + b.task() + " is safe (the input's age and the "
                    + "stopping distance alone use up its range).";
        }
        String text = " Reaction rule (the runs' advice): largest safe period of " + b.task() + " " + num(b.ms(), 1)
                + " ms (mean over " + b.sets() + " set(s)); ";
        var first = onAxis(group).stream().filter(s -> s.runsWithCollisions() > 0)
                .min(Comparator.comparingLong(SetSummary::sweptPeriodMs));
        if (first.isPresent()) {
            return text + "the shortest period with a collision, " + first.get().sweptPeriodMs() + " ms, is "
                    + num(first.get().sweptPeriodMs() / b.ms(), 2) + " x that bound.";
        }
        long longest = onAxis(group).stream().mapToLong(SetSummary::sweptPeriodMs).max().orElse(0);
        return text + "no run collided up to the longest period, " + longest + " ms (" + num(longest / b.ms(), 2)
                + " x that bound).";
    }

    private void fast(List<SetSummary> group, Scope scope) {
        List<SetSummary> fastSets = onAxis(group).stream().filter(s -> s.sweptPeriodMs() <= FAST_AT_MOST_MS).toList();
        if (fastSets.isEmpty()) {
            unjudged(FAST, scope, "no set with a period of " + FAST_AT_MOST_MS + " ms or less"
                    + periodsHere(group));
            return;
        }
        boolean allMost = fastSets.stream().allMatch(s -> errors(s) >= MAJORITY * s.runs());
        boolean none = fastSets.stream().allMatch(s -> errors(s) == 0);
        Verdict v = allMost ? Verdict.REPRODUCED : none ? Verdict.NOT_COMPARABLE : Verdict.MIXED;
        List<String> parts = new ArrayList<>();
        for (SetSummary s : fastSets) {
            parts.add(robot(s));
        }
        onAxis(group).stream().filter(s -> s.sweptPeriodMs() == SLOW_ABOVE_MS).findFirst()
                .ifPresent(s -> parts.add("for comparison, " + robot(s)));
        judged(FAST, scope, v, String.join("; ", parts) + "." + (v == Verdict.NOT_COMPARABLE ? " " + LOCK_UP_MECHANISM
                : ""), "a run 'locks up' when its process fails or leaves no report (outcome error); reproduced if at least "
                + pct(MAJORITY) + " of the runs of every set at " + FAST_AT_MOST_MS + " ms or less lock up; not comparable "
                + "if none does (the paper's lock-up came from a starved machine that this setup does not have); mixed "
                + "otherwise");
    }

    private static String robot(SetSummary s) {
        Misses all = s.misses().get(ExperimentSummary.ALL_TASKS);
        String skipped = all.skipped() == null ? "skipped releases not recorded"
                : all.skipped() + " releases skipped (" + pct(all.releases() == 0 ? 0 : (double) all.skipped() / all.releases())
                + " of " + all.releases() + ")";
        return s.name() + " (" + s.sweptPeriodMs() + " ms): " + errors(s) + " of " + s.runs() + " runs locked up, "
                + s.completed() + " completed, outcomes " + s.outcomes() + ", " + s.runsWithCollisions() + " of "
                + s.measuredRuns() + " collided, misses " + num(all.missPct(), 2) + "% of all four tasks' releases, " + skipped
                + (s.runTimeS().mean() == null ? "" : ", mean run time " + num(s.runTimeS().mean(), 1) + " s");
    }

    private static int errors(SetSummary s) {
        return s.outcomes().getOrDefault(RunResult.ERROR, 0);
    }

    private void missesFall() {
        Map<String, List<double[]>> series = new LinkedHashMap<>();
        for (String task : PeriodSet.TASKS) {
            List<double[]> points = new ArrayList<>();
            for (SetSummary s : sets) {
                Double pct = s.misses().get(task).missPct();
                if (pct != null) {
                    points.add(new double[] {s.periodsMs().get(task), pct});
                }
            }
            series.put(task, points);
        }
        List<double[]> all = new ArrayList<>();
        for (SetSummary s : onAxis(sets)) {
            Double pct = s.misses().get(ExperimentSummary.ALL_TASKS).missPct();
            if (pct != null) {
                all.add(new double[] {s.sweptPeriodMs(), pct});
            }
        }
        series.put("all four (against the swept period)", all);
        series.values().removeIf(points -> points.stream().mapToDouble(p -> p[0]).distinct().count() < MIN_PERIODS);
        if (series.isEmpty()) {
            unjudged(MISSES_FALL, Scope.PAPER, "no task's period takes " + MIN_PERIODS
                    + " or more values across the sets");
            return;
        }
        List<String> parts = new ArrayList<>();
        int falls = 0;
        for (Map.Entry<String, List<double[]>> e : series.entrySet()) {
            double[] x = e.getValue().stream().mapToDouble(p -> p[0]).toArray();
            double[] y = e.getValue().stream().mapToDouble(p -> p[1]).toArray();
            double rho = new SpearmansCorrelation().correlation(x, y);
            boolean fall = rho <= FALLS_RHO;
            falls += fall ? 1 : 0;
            double[] first = e.getValue().stream().min(Comparator.comparingDouble(p -> p[0])).orElseThrow();
            double[] last = e.getValue().stream().max(Comparator.comparingDouble(p -> p[0])).orElseThrow();
            parts.add(e.getKey() + ": rho " + (Double.isNaN(rho) ? "undefined (the same miss % everywhere)" : num(rho, 2))
                    + " over " + x.length + " sets, " + num(first[1], 2) + "% at " + (long) first[0] + " ms, "
                    + num(last[1], 2) + "% at " + (long) last[0] + " ms");
        }
        Verdict v = falls == series.size() ? Verdict.REPRODUCED : falls == 0 ? Verdict.NOT_REPRODUCED : Verdict.MIXED;
        judged(MISSES_FALL, Scope.PAPER, v, String.join("; ", parts) + ".", "for each task whose period takes at least "
                + MIN_PERIODS + " values across the sets (its miss % against its period), and for all four tasks against "
                + "the swept period: Spearman's rank correlation rho; a series falls if rho <= " + FALLS_RHO
                + "; reproduced if every series falls, not reproduced if none does, mixed otherwise");
    }

    private Map<Integer, SetSummary> paperSets() {
        Map<Integer, SetSummary> paper = new TreeMap<>();
        List<PaperReference.PaperSet> published = PaperReference.published().sets();
        for (SetSummary s : sets) {
            PaperReference.PaperSet match = s.paperSet();
            if (match != null) {
                paper.putIfAbsent(published.indexOf(match) + 1, s);
            }
        }
        return paper;
    }

    private void setOneDiffers(Map<Integer, SetSummary> paper) {
        List<int[]> pairs = List.of(new int[] {1, 4}, new int[] {1, 5});
        List<String> parts = new ArrayList<>();
        int agree = 0;
        for (int[] pair : pairs) {
            WelchTest t = test(paper, pair[0], pair[1], "run_time_s");
            String missing = missing(paper, pair, t);
            if (missing != null) {
                unjudged(T_SET1, Scope.PAPER, missing);
                return;
            }
            double a = paper.get(pair[0]).runTimeS().mean();
            double b = paper.get(pair[1]).runTimeS().mean();
            boolean ok = t.p() < ALPHA && a < b;
            agree += ok ? 1 : 0;
            parts.add("Set " + pair[0] + " vs Set " + pair[1] + ": " + num(a, 2) + " s vs " + num(b, 2) + " s, p = "
                    + num(t.p(), 4));
        }
        judged(T_SET1, Scope.PAPER, verdict(agree, pairs.size()), String.join("; ", parts)
                + " (paper: 266.95 s vs 276.97 s and 272.68 s, both statistically different).",
                "Welch's two-sided t-test on the completed runs; a pair agrees if p < " + ALPHA
                        + " and Set 1's mean is the lower; reproduced if both agree, not reproduced if neither, mixed otherwise");
    }

    private void onTheVerge(Map<Integer, SetSummary> paper) {
        List<int[]> pairs = List.of(new int[] {2, 4}, new int[] {3, 4}, new int[] {4, 5});
        List<String> paperConfidence = List.of("82%", "85%", "79%");
        List<String> parts = new ArrayList<>();
        int agree = 0;
        for (int i = 0; i < pairs.size(); i++) {
            int[] pair = pairs.get(i);
            WelchTest t = test(paper, pair[0], pair[1], "run_time_s");
            String missing = missing(paper, pair, t);
            if (missing != null) {
                unjudged(T_VERGE, Scope.PAPER, missing);
                return;
            }
            agree += t.confidence() >= VERGE_MIN && t.confidence() < VERGE_MAX ? 1 : 0;
            parts.add("Set " + pair[0] + " vs Set " + pair[1] + ": confidence " + pct(t.confidence()) + " (paper "
                    + paperConfidence.get(i) + ")");
        }
        judged(T_VERGE, Scope.PAPER, verdict(agree, pairs.size()), String.join("; ", parts) + ".",
                "Welch's two-sided t-test on the completed runs, confidence = 1 - p; a pair agrees if its confidence is at least "
                        + pct(VERGE_MIN) + " and below " + pct(VERGE_MAX) + "; reproduced if all three agree, not reproduced "
                        + "if none does, mixed otherwise");
    }

    private void distancesAlike(Map<Integer, SetSummary> paper) {
        List<String> parts = new ArrayList<>();
        List<String> skipped = new ArrayList<>();
        int different = 0;
        int tested = 0;
        List<Integer> numbers = new ArrayList<>(paper.keySet());
        for (int i = 0; i < numbers.size(); i++) {
            for (int j = i + 1; j < numbers.size(); j++) {
                WelchTest t = test(paper, numbers.get(i), numbers.get(j), "distance_to_finish_m");
                String pair = "Set " + numbers.get(i) + " vs Set " + numbers.get(j);
                if (t == null || !t.applicable()) {
                    skipped.add(pair);
                    continue;
                }
                tested++;
                if (t.p() < ALPHA) {
                    different++;
                    parts.add(pair + " p = " + num(t.p(), 4));
                }
            }
        }
        if (tested == 0) {
            unjudged(T_DISTANCE, Scope.PAPER, numbers.size() < 2
                    ? "fewer than two of the paper's sets (at the paper's top speed) were run"
                    : "no t-test between the paper's sets is defined (" + String.join(", ", skipped)
                            + ": fewer than two runs, or no variance)");
            return;
        }
        Verdict v = different == 0 ? Verdict.REPRODUCED : different * 2 >= tested ? Verdict.NOT_REPRODUCED : Verdict.MIXED;
        List<String> blind = new ArrayList<>();
        if (v == Verdict.REPRODUCED) {
            for (int i = 0; i < numbers.size(); i++) {
                for (int j = i + 1; j < numbers.size(); j++) {
                    WelchTest t = test(paper, numbers.get(i), numbers.get(j), "distance_to_finish_m");
                    double paperDiff = Math.abs(PaperReference.published().sets().get(numbers.get(i) - 1).distanceMeanM()
                            - PaperReference.published().sets().get(numbers.get(j) - 1).distanceMeanM());
                    if (t != null && t.applicable() && t.detectableDifference() > paperDiff) {
                        blind.add("Set " + numbers.get(i) + " vs Set " + numbers.get(j) + " detects " + num(
                                t.detectableDifference(), 3) + " m, the paper's difference is " + num(paperDiff, 3) + " m");
                    }
                }
            }
            if (!blind.isEmpty()) {
                v = Verdict.INCONCLUSIVE;
            }
        }
        String evidence = different + " of " + tested + " pairs of the paper's sets (" + names(paper, numbers)
                + ") differ with p < " + ALPHA + (parts.isEmpty() ? "" : ": " + String.join("; ", parts))
                + (skipped.isEmpty() ? "" : "; not testable: " + String.join(", ", skipped))
                + (blind.isEmpty() ? "" : "; too weak to see the paper's differences: " + String.join("; ", blind)) + ".";
        judged(T_DISTANCE, Scope.PAPER, v, evidence, "Welch's two-sided t-test between every pair of the paper's sets "
                + "present, on every run that ended on the course; reproduced if no pair has p < " + ALPHA
                + " and every test could have detected the paper's difference of the two sets' means (the smallest difference "
                + "detectable at alpha " + WelchTest.ALPHA + " with " + pct(WelchTest.POWER) + " power, from the observed "
                + "spread and n, is at most the paper's); inconclusive if no pair differs but a test could not have; not "
                + "reproduced if at least half the pairs differ, mixed otherwise (no correction for multiple tests, like the "
                + "paper)");
    }

    private void setThree(Map<Integer, SetSummary> paper) {
        if (paper.size() < 5 || paper.values().stream().anyMatch(s -> s.runTimeS().sd() == null)) {
            unjudged(SET3, Scope.PAPER, "needs all five paper sets with at least two completed runs each; have "
                    + (paper.isEmpty() ? "none" : names(paper, new ArrayList<>(paper.keySet()))));
            return;
        }
        int fastest = argBest(paper, s -> -s.runTimeS().mean());
        int widest = argBest(paper, s -> s.runTimeS().sd());
        int agree = (fastest == 3 ? 1 : 0) + (widest == 3 ? 1 : 0);
        judged(SET3, Scope.PAPER, verdict(agree, 2), "fastest mean run time: Set " + fastest + " ("
                + num(paper.get(fastest).runTimeS().mean(), 2) + " s); highest SD: Set " + widest + " ("
                + num(paper.get(widest).runTimeS().sd(), 2) + " s); Set 3: " + num(paper.get(3).runTimeS().mean(), 2)
                + " s +- " + num(paper.get(3).runTimeS().sd(), 2) + " s (paper: 265.89 +- 11.19 s).",
                "reproduced if Set 3 has both the lowest mean and the highest standard deviation of the run time, "
                        + "not reproduced if neither, mixed if one");
    }

    private void almostIdentical(Map<Integer, SetSummary> paper) {
        List<SetSummary> withTimes = paper.values().stream().filter(s -> s.runTimeS().mean() != null).toList();
        List<SetSummary> withDistances = paper.values().stream().filter(s -> s.distanceToFinishM().mean() != null).toList();
        if (withTimes.size() < 2 || withDistances.size() < 2) {
            unjudged(SAME, Scope.PAPER, "needs at least two of the paper's sets with a mean run time and a mean "
                    + "distance to the finish; have " + withTimes.size() + " and " + withDistances.size());
            return;
        }
        double time = spread(withTimes, s -> s.runTimeS().mean());
        double distance = spread(withDistances, s -> s.distanceToFinishM().mean());
        int agree = (time <= SAME_RUN_TIME ? 1 : 0) + (distance <= SAME_DISTANCE ? 1 : 0);
        judged(SAME, Scope.PAPER, verdict(agree, 2), "over " + names(paper, new ArrayList<>(paper.keySet()))
                + ": the set means of the run time span " + pct(time) + " of their mean, those of the distance to the finish "
                + pct(distance) + " (paper: 4.2% and 13.6%).", "spread = (largest set mean - smallest) / mean of the set "
                + "means; reproduced if at most " + pct(SAME_RUN_TIME) + " for run time and at most " + pct(SAME_DISTANCE)
                + " for distance (the paper's own spreads, rounded up), not reproduced if neither, mixed if one");
    }

    private void fig7(Map<Integer, SetSummary> paper) {
        List<String> parts = new ArrayList<>();
        int agree = 0;
        int judged = 0;
        for (int n : List.of(1, 4, 5)) {
            SetSummary s = paper.get(n);
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
            unjudged(FIG7, Scope.PAPER, "none of the paper's Sets 1, 4 and 5 (at the paper's top speed) was run");
            return;
        }
        judged(FIG7, Scope.PAPER, verdict(agree, judged), String.join("; ", parts) + ".",
                "a set agrees if its miss % is strictly ordered planner > occupancy > waypoint > obstacle; reproduced if "
                        + "every one of Sets 1, 4 and 5 present agrees, not reproduced if none does, mixed otherwise");
    }

    private void setOneMisses(Map<Integer, SetSummary> paper) {
        List<SetSummary> withMisses = paper.values().stream()
                .filter(s -> s.misses().get(ExperimentSummary.ALL_TASKS).missPct() != null).toList();
        if (!paper.containsKey(1) || withMisses.size() < 2 || !withMisses.contains(paper.get(1))) {
            unjudged(SET1_MISSES, Scope.PAPER, "needs the paper's Set 1 and another paper set with misses "
                    + "counted; have " + (paper.isEmpty() ? "none" : names(paper, new ArrayList<>(paper.keySet()))));
            return;
        }
        int highest = argBest(paper.entrySet().stream().filter(e -> withMisses.contains(e.getValue()))
                .collect(java.util.stream.Collectors.toMap(Map.Entry::getKey, Map.Entry::getValue, (a, b) -> a,
                        TreeMap::new)), s -> s.misses().get(ExperimentSummary.ALL_TASKS).missPct());
        List<String> parts = new ArrayList<>();
        paper.forEach((n, s) -> parts.add("Set " + n + " " + num(s.misses().get(ExperimentSummary.ALL_TASKS).missPct(), 2)
                + "%"));
        judged(SET1_MISSES, Scope.PAPER, highest == 1 ? Verdict.REPRODUCED : Verdict.NOT_REPRODUCED,
                "misses of all four tasks' releases: " + String.join(", ", parts) + "; highest: Set " + highest + ".",
                "reproduced if Set 1 has the highest miss % of the paper's sets present, not reproduced otherwise");
    }

    private void spreadTwice(Map<Integer, SetSummary> paper) {
        List<Integer> wide = List.of(2, 3);
        List<Integer> narrow = List.of(1, 4, 5);
        boolean all = java.util.stream.Stream.concat(wide.stream(), narrow.stream())
                .allMatch(n -> paper.containsKey(n) && paper.get(n).runTimeS().sd() != null);
        if (!all) {
            unjudged(SPREAD, Scope.PAPER, "needs all five paper sets with at least two completed runs each; have "
                    + (paper.isEmpty() ? "none" : names(paper, new ArrayList<>(paper.keySet()))));
            return;
        }
        double wideSd = wide.stream().mapToDouble(n -> paper.get(n).runTimeS().sd()).average().orElseThrow();
        double narrowSd = narrow.stream().mapToDouble(n -> paper.get(n).runTimeS().sd()).average().orElseThrow();
        double ratio = wideSd / narrowSd;
        Verdict v = ratio >= SPREAD_RATIO_MIN ? Verdict.REPRODUCED : ratio < SPREAD_RATIO_NONE ? Verdict.NOT_REPRODUCED
                : Verdict.MIXED;
        List<PaperReference.PaperSet> published = PaperReference.published().sets();
        double paperWide = wide.stream().mapToDouble(n -> published.get(n - 1).runTimeSdS()).average().orElseThrow();
        double paperNarrow = narrow.stream().mapToDouble(n -> published.get(n - 1).runTimeSdS()).average().orElseThrow();
        judged(SPREAD, Scope.PAPER, v, "mean SD of the run time: Sets 2 and 3 " + num(wideSd, 2) + " s, Sets 1, 4 and 5 "
                + num(narrowSd, 2) + " s, ratio " + num(ratio, 2) + " (paper: " + num(paperWide, 2) + " s and "
                + num(paperNarrow, 2) + " s, ratio " + num(paperWide / paperNarrow, 2) + ").", "ratio = mean SD of Sets 2 and 3 over mean SD of Sets 1, 4 and 5; reproduced if at "
                + "least " + SPREAD_RATIO_MIN + ", not reproduced if below " + SPREAD_RATIO_NONE + ", mixed between");
    }

    private static Verdict verdict(int agree, int of) {
        return agree == of ? Verdict.REPRODUCED : agree == 0 ? Verdict.NOT_REPRODUCED : Verdict.MIXED;
    }

    private WelchTest test(Map<Integer, SetSummary> paper, int a, int b, String quantity) {
        SetSummary x = paper.get(a);
        SetSummary y = paper.get(b);
        if (x == null || y == null) {
            return null;
        }
        for (PairTest p : tests.getOrDefault(quantity, List.of())) {
            if (p.setA() == x.set() && p.setB() == y.set() || p.setA() == y.set() && p.setB() == x.set()) {
                return p.test();
            }
        }
        return null;
    }

    private static String missing(Map<Integer, SetSummary> paper, int[] pair, WelchTest t) {
        for (int n : pair) {
            if (!paper.containsKey(n)) {
                return "the paper's Set " + n + " (" + PaperReference.published().sets().get(n - 1).periods().shortLabel()
                        + " ms at the paper's top speed) was not run";
            }
        }
        if (t == null || !t.applicable()) {
            return "the t-test of Set " + pair[0] + " vs Set " + pair[1] + " is not defined"
                    + (t == null ? "" : ": " + t.note());
        }
        return null;
    }

    private static int argBest(Map<Integer, SetSummary> paper, Function<SetSummary, Double> score) {
        return paper.entrySet().stream().max(Comparator.comparingDouble(e -> score.apply(e.getValue())))
                .orElseThrow().getKey();
    }

    private static double spread(List<SetSummary> sets, Function<SetSummary, Double> mean) {
        double max = sets.stream().mapToDouble(mean::apply).max().orElseThrow();
        double min = sets.stream().mapToDouble(mean::apply).min().orElseThrow();
        double avg = sets.stream().mapToDouble(mean::apply).average().orElseThrow();
        return (max - min) / avg;
    }

    private static List<SetSummary> onAxis(List<SetSummary> group) {
        return group.stream().filter(s -> s.sweptPeriodMs() != null).toList();
    }

    private static String periodsHere(List<SetSummary> group) {
        List<Long> periods = onAxis(group).stream().map(SetSummary::sweptPeriodMs).distinct().sorted().toList();
        return periods.isEmpty() ? " (the sets do not differ in one swept period)"
                : " (periods here: " + String.join(", ", periods.stream().map(p -> p + " ms").toList()) + ")";
    }

    /** @return e.g. {@code Set 2 (our "obstacle 10 ms"), Set 5}: the paper's numbers, with our name where it differs */
    private static String names(Map<Integer, SetSummary> paper, List<Integer> numbers) {
        return String.join(", ", numbers.stream().map(n -> {
            String ours = paper.get(n).name();
            return ours.equals("Set " + n) ? "Set " + n : "Set " + n + " (our '" + ours + "')";
        }).toList());
    }

    private static String speedLabel(Double speedMps) {
        return speedMps == null ? "run's default top speed" : PeriodSet.plainSpeed(speedMps) + " m/s";
    }

    private static String pct(double share) {
        return num(100 * share, 1) + "%";
    }

    private static String num(Double v, int decimals) {
        return v == null || !Double.isFinite(v) ? "n/a" : String.format(Locale.ROOT, "%." + decimals + "f", v);
    }
}
