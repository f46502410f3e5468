package io.rtaware.experiment.claims;

import io.rtaware.experiment.ExperimentSummary.PairTest;
import io.rtaware.experiment.ExperimentSummary.SetSummary;
import io.rtaware.experiment.RunResult;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The paper's claims, each given a verdict computed from an experiment's results by an explicit
 * rule (stated with each verdict and in the report), never set by hand; and, apart from them,
 * rtaware's own rules checked by the same runs ({@link RuleVerdict}). Each family of claims is
 * one {@link ClaimRule} that owns its stable id, its words and its judging; a claim whose data the
 * experiment does not have (no set above 100 ms, no paper Set 4, no variance for a t-test) is not
 * given a verdict but listed as not evaluated, with the reason.
 *
 * <p>The period of a set, for the claims about periods, is {@link SetSummary#sweptPeriodMs()}:
 * the period its swept tasks share. Claims about too-slow and too-fast periods are judged per top
 * speed when the sets differ in speed. Tables I and II and Fig. 7 are judged on the sets whose
 * periods are those of a paper set and whose top speed is the paper's (or {@code run}'s default).
 */
public final class PaperClaims {

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
    /** The rule's bound counts as near when the first period with a collision is at most this many times it. */
    public static final double RULE_NEAR = 2.0;
    /** Ratio of the mean SD of Sets 2 and 3 to that of Sets 1, 4, 5 from which the spread claim holds. */
    public static final double SPREAD_RATIO_MIN = 1.5;
    /** Ratio below which it does not hold at all. */
    public static final double SPREAD_RATIO_NONE = 1.25;

    /** Runs per set below which a verdict says it rests on a small sample. */
    public static final int SMALL_SAMPLE_RUNS = 5;

    /** Why no lock-up here says nothing against the paper's. */
    public static final String LOCK_UP_MECHANISM = "The paper's lock-up came from a 1.66 GHz machine starved by the "
            + "controller and the Player server sharing it; here the simulator is light and rtaware skips the releases "
            + "it cannot make, so the mechanism cannot be reproduced and no lock-up says nothing against the paper.";

    /** Every family of the paper's claims, in the order of the verdicts. */
    private static final List<ClaimRule> FAMILIES = List.of(
            new CollisionClaims.SlowHits(),
            new CollisionClaims.FastLocksUp(),
            new MissClaims.MissesFall(),
            new TableClaims.Set1Faster(),
            new TableClaims.OnTheVerge(),
            new TableClaims.DistancesAlike(),
            new TableClaims.Set3FastestWidest(),
            new TableClaims.AlmostIdentical(),
            new MissClaims.Fig7PlannerMost(),
            new MissClaims.Fig8Set1MostMisses(),
            new TableClaims.SpreadTwice(),
            new MissClaims.Fig7Set1HighestPerTask(),
            new MissClaims.ComputationOrder(),
            new ConclusionClaim(),
            new SweepClaims.AvoiderTooFast(),
            new SweepClaims.SamplingAdvice(),
            new SweepClaims.PlannerCanSlow(),
            new NotMeasured("bad-map-bad-path", "Section V: an occupancy grid run at the wrong rate maps the room wrongly, "
                    + "so the planner plans a wrong path and the robot moves through an obstacle", "no experiment here "
                    + "varies the occupancy grid's period alone, and results.csv records neither the map's error against "
                    + "the world nor whether a planned path crossed an obstacle; the sweeps that slow the grid "
                    + "(sweep-all, office-all) slow the avoider with it, whose collisions 'periods above 100 ms' counts"));

    /** rtaware's own rules the runs can check, apart from the paper's claims. */
    private static final List<ClaimRule> RULES = List.of(new ReactionRule());

    /**
     * @param claims the paper's claims with a verdict
     * @param notEvaluated the paper's claims without one
     * @param rules rtaware's own rules, checked or not evaluated
     */
    public record Verdicts(List<Claim> claims, List<NotEvaluated> notEvaluated, List<RuleVerdict> rules) {
    }

    private PaperClaims() {
    }

    /** @return the stable id of every family of the paper's claims, in the order of the verdicts */
    public static List<String> familyIds() {
        return FAMILIES.stream().map(ClaimRule::id).toList();
    }

    /** @return the stable id of every one of rtaware's own rules */
    public static List<String> ruleIds() {
        return RULES.stream().map(ClaimRule::id).toList();
    }

    /**
     * What the claims are judged on: one selection of an experiment's runs, summarized.
     *
     * @param sets the sets, summarized
     * @param tests the Welch tests between them per quantity
     * @param rows the runs themselves (for the tests blocked on the world seed)
     */
    public record Results(List<SetSummary> sets, Map<String, List<PairTest>> tests, List<RunResult> rows) {
    }

    /**
     * Judges every claim on the runs the summary uses and again on all runs: each verdict carries
     * the other ({@link Claim#verdictAllRuns()}) and is {@link Claim#fragile()} when they differ.
     *
     * @param used the runs the summary uses (the quiet ones, unless busy runs are included)
     * @param all every run of the experiment ({@code used} itself when nothing was left out)
     * @param scenario the experiment's scenario, named in the claims that depend on the course
     *     (the collision claim and the reaction rule's) unless it is the paper's room, or null
     * @return the verdicts, in a fixed order of claims
     */
    public static Verdicts evaluate(Results used, Results all, String scenario) {
        Verdicts quiet = judge(used, scenario);
        Verdicts whole = all == used ? quiet : judge(all, scenario);
        Map<String, String> allRuns = new HashMap<>();
        whole.claims().forEach(c -> allRuns.put(c.id(), c.verdict().json()));
        whole.rules().forEach(r -> allRuns.put(r.id(), r.verdict()));
        return new Verdicts(
                quiet.claims().stream().map(c -> c.onAllRuns(allRuns.getOrDefault(c.id(), NotEvaluated.NOT_EVALUATED)))
                        .toList(),
                quiet.notEvaluated().stream()
                        .map(n -> n.onAllRuns(allRuns.getOrDefault(n.id(), NotEvaluated.NOT_EVALUATED))).toList(),
                quiet.rules().stream().map(r -> r.onAllRuns(allRuns.getOrDefault(r.id(), NotEvaluated.NOT_EVALUATED)))
                        .toList());
    }

    private static Verdicts judge(Results results, String scenario) {
        Judging j = new Judging(results, scenario);
        FAMILIES.forEach(f -> f.judge(j));
        List<RuleVerdict> rules = new ArrayList<>();
        for (ClaimRule rule : RULES) {
            Judging r = new Judging(results, scenario);
            rule.judge(r);
            r.claims().forEach(c -> rules.add(RuleVerdict.of(c)));
            r.notEvaluated().forEach(n -> rules.add(RuleVerdict.of(n)));
        }
        return new Verdicts(j.claims(), j.notEvaluated(), List.copyOf(rules));
    }

    /**
     * @param sets sets of one top speed
     * @return the largest safe period the runs' advice gave by the reaction rule (the mean over the
     *     sets that report it), ms, or null when no run reports one
     */
    public static Double reactionRuleBoundMs(List<SetSummary> sets) {
        return ReactionRule.boundMs(sets);
    }
}
