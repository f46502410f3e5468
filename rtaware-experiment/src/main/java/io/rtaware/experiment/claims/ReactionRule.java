package io.rtaware.experiment.claims;

import static io.rtaware.experiment.claims.Judging.num;
import static io.rtaware.experiment.claims.Judging.onAxis;
import static io.rtaware.experiment.claims.Judging.periodsHere;

import io.rtaware.experiment.ExperimentSummary.SetSummary;
import io.rtaware.experiment.PeriodSet;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.Objects;
import java.util.Optional;

/**
 * rtaware's own reaction rule (the period advice's, not the paper's) checked by the runs: its
 * largest safe period (the mean of the runs' advice) against the shortest swept period at which a
 * run collided. Checked per course and top speed. Where the rule finds no safe period it names no
 * bound to check, and is not evaluated.
 */
final class ReactionRule extends ClaimFamily {

    ReactionRule() {
        super("reaction-rule-bound", "rtaware's reaction rule (the period advice): collisions begin near its largest "
                + "safe period");
    }

    @Override
    public void judge(Judging j) {
        j.bySpeed().forEach((speed, group) -> judge(j, group, j.atSpeed(j.course(), speed)));
    }

    private void judge(Judging j, List<SetSummary> group, Scope scope) {
        Double bound = boundMs(group);
        List<SetSummary> axis = onAxis(group).stream().filter(s -> s.measuredRuns() > 0).toList();
        if (bound == null || axis.size() < 2) {
            j.unjudged(this, scope, bound == null ? "no run reports the reaction rule's largest safe period"
                    : "fewer than two swept periods with runs on the course" + periodsHere(group));
            return;
        }
        Optional<SetSummary> first = firstCollision(axis);
        long longest = axis.stream().mapToLong(SetSummary::sweptPeriodMs).max().orElseThrow();
        if (bound <= 0) {
            j.unjudged(this, scope, "the rule finds no safe period here (the input's age and the stopping distance "
                    + "alone use up the avoider's range): it predicts collisions at every period and names no bound for "
                    + "the runs to check; runs with a collision: " + String.join("; ", axis.stream()
                    .map(s -> s.sweptPeriodMs() + " ms " + s.collisions95().text()).toList()));
            return;
        }
        if (first.isEmpty() && longest < bound) {
            j.unjudged(this, scope, "no swept period reaches the rule's largest safe period ("
                    + num(bound, 1) + " ms; the longest is " + longest + " ms) and no run collided: the runs agree with "
                    + "the rule without testing it");
            return;
        }
        Verdict v;
        String evidence;
        if (first.isEmpty()) {
            v = longest > PaperClaims.RULE_NEAR * bound ? Verdict.NOT_REPRODUCED : Verdict.MIXED;
            evidence = "largest safe period " + num(bound, 1) + " ms; no run collided up to " + longest + " ms ("
                    + num(longest / bound, 2) + " x the bound)";
        } else {
            double ratio = first.get().sweptPeriodMs() / bound;
            v = ratio < 1 ? Verdict.NOT_REPRODUCED : ratio <= PaperClaims.RULE_NEAR ? Verdict.REPRODUCED : Verdict.MIXED;
            evidence = "largest safe period " + num(bound, 1) + " ms; the shortest period with a collision is "
                    + first.get().sweptPeriodMs() + " ms (" + first.get().name() + ", " + first.get().runsWithCollisions()
                    + " of " + first.get().measuredRuns() + " runs), " + num(ratio, 2) + " x the bound";
        }
        j.judged(this, scope, v, evidence + ".", "holds if the shortest swept period at which a run collided lies "
                + "between the bound and " + num(PaperClaims.RULE_NEAR, 1) + " x the bound; fails if runs collided below "
                + "the bound (the rule is unsafe) or none collided up to beyond " + num(PaperClaims.RULE_NEAR, 1)
                + " x it (the rule is far too cautious); mixed otherwise",
                    axis, SetSummary::measuredRuns);
    }

    /** The reaction rule's largest safe period for one task: the mean over the sets whose runs' advice gave it. */
    private record Bound(String task, double ms, int sets) {
    }

    private static Optional<Bound> bound(List<SetSummary> group) {
        for (String task : PeriodSet.TASKS) {
            double[] bounds = group.stream().map(s -> s.misses().get(task).maxSafePeriodMsMean()).filter(Objects::nonNull)
                    .mapToDouble(Double::doubleValue).toArray();
            if (bounds.length > 0) {
                return Optional.of(new Bound(task, Arrays.stream(bounds).average().orElseThrow(), bounds.length));
            }
        }
        return Optional.empty();
    }

    /**
     * @param group sets of one top speed
     * @return the largest safe period the runs' advice gave by the reaction rule (the mean over the
     *     sets that report it), ms, or null when no run reports one
     */
    static Double boundMs(List<SetSummary> group) {
        return bound(group).map(Bound::ms).orElse(null);
    }

    /** @return the set with the shortest swept period at which a run collided, if any */
    static Optional<SetSummary> firstCollision(List<SetSummary> group) {
        return onAxis(group).stream().filter(s -> s.runsWithCollisions() > 0)
                .min(Comparator.comparingLong(SetSummary::sweptPeriodMs));
    }

    /**
     * @param group the sets of one top speed
     * @return how the shortest period with a collision compares with the largest safe period the
     *     runs' advice gave by the reaction rule, or "" when no run reports that bound
     */
    static String comparedWithCollisions(List<SetSummary> group) {
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
        Optional<SetSummary> first = firstCollision(group);
        if (first.isPresent()) {
            return text + "the shortest period with a collision, " + first.get().sweptPeriodMs() + " ms, is "
                    + num(first.get().sweptPeriodMs() / b.ms(), 2) + " x that bound.";
        }
        long longest = onAxis(group).stream().mapToLong(SetSummary::sweptPeriodMs).max().orElse(0);
        return text + "no run collided up to the longest period, " + longest + " ms (" + num(longest / b.ms(), 2)
                + " x that bound).";
    }
}
