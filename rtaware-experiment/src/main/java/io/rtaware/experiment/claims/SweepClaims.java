package io.rtaware.experiment.claims;

import static io.rtaware.experiment.claims.Judging.combine;
import static io.rtaware.experiment.claims.Judging.num;
import static io.rtaware.experiment.claims.Judging.onAxis;
import static io.rtaware.experiment.claims.Judging.pct;
import static io.rtaware.experiment.claims.Judging.periodsHere;

import io.rtaware.experiment.ExperimentSummary;
import io.rtaware.experiment.ExperimentSummary.SetSummary;
import io.rtaware.experiment.Sweep;
import io.rtaware.experiment.stats.FisherExact;
import io.rtaware.experiment.stats.RateInterval;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.function.ToIntFunction;

/**
 * The paper's claims about how fast a task should run, judged from sweeps of a task's period
 * (Sections V and VII). Each is judged per top speed and the verdicts combined: one verdict when
 * they agree, mixed when they do not.
 */
final class SweepClaims {

    private SweepClaims() {
    }

    /** One top speed's verdict and its evidence. */
    private record Group(Verdict verdict, String evidence, List<SetSummary> cells) {
    }

    /** Judges each top speed with {@code judge} and gives the claim one verdict, or the reasons for none. */
    private static void perSpeed(ClaimRule rule, Judging j, GroupJudge judge, String how) {
        Map<String, List<SetSummary>> bySpeed = j.bySpeed();
        List<Group> groups = new ArrayList<>();
        List<String> reasons = new ArrayList<>();
        bySpeed.forEach((speed, sets) -> {
            List<String> why = new ArrayList<>();
            Group g = judge.judge(sets, why);
            String at = bySpeed.size() > 1 ? "at " + speed + ": " : "";
            if (g == null) {
                reasons.add(at + String.join("; ", why));
            } else {
                groups.add(new Group(g.verdict(), at + g.evidence(), g.cells()));
            }
        });
        if (groups.isEmpty()) {
            j.unjudged(rule, Scope.PAPER, String.join("; ", reasons));
            return;
        }
        j.judged(rule, Scope.PAPER, combine(groups.stream().map(Group::verdict).toList()),
                String.join(" ", groups.stream().map(Group::evidence).toList())
                        + (reasons.isEmpty() ? "" : " Not judged " + String.join("; ", reasons) + "."),
                how + (bySpeed.size() > 1 ? "; judged per top speed, the verdicts combined (mixed if they differ)" : ""),
                groups.stream().flatMap(g -> g.cells().stream()).toList(), SetSummary::measuredRuns);
    }

    /** How one top speed's sets are judged: a verdict, or null with the reasons added to {@code why}. */
    private interface GroupJudge {
        Group judge(List<SetSummary> sets, List<String> why);
    }

    private static int sum(List<SetSummary> sets, ToIntFunction<SetSummary> count) {
        return sets.stream().mapToInt(count).sum();
    }

    private static String rate(List<SetSummary> sets, ToIntFunction<SetSummary> hits, ToIntFunction<SetSummary> of) {
        int n = sum(sets, of);
        return n == 0 ? "no runs" : RateInterval.of(sum(sets, hits), n).text();
    }

    /** "If LASEROBSTACLEAVOIDANCE is run at too fast a period then it may cause the robot to hit an obstacle." */
    static final class AvoiderTooFast extends ClaimFamily {

        AvoiderTooFast() {
            super("avoider-too-fast-hits",
                    "Section V: an obstacle avoider run too fast (5 ms or less) makes the robot hit obstacles");
        }

        @Override
        public void judge(Judging j) {
            boolean swept = j.sweptTasks().contains("obstacle");
            perSpeed(this, j, (sets, why) -> {
                if (!swept) {
                    why.add("the avoider's period does not vary between the sets");
                    return null;
                }
                List<SetSummary> fast = onAxis(sets).stream()
                        .filter(s -> s.sweptPeriodMs() <= PaperClaims.FAST_AT_MOST_MS && s.measuredRuns() > 0).toList();
                List<SetSummary> usual = onAxis(sets).stream().filter(s -> s.sweptPeriodMs() > PaperClaims.FAST_AT_MOST_MS
                        && s.sweptPeriodMs() <= PaperClaims.SLOW_ABOVE_MS && s.measuredRuns() > 0).toList();
                if (fast.isEmpty()) {
                    why.add("no set runs the avoider at " + PaperClaims.FAST_AT_MOST_MS + " ms or less with a run on the "
                            + "course" + periodsHere(sets));
                    return null;
                }
                boolean allMost = fast.stream().allMatch(s -> s.collisionRate() >= PaperClaims.MAJORITY);
                boolean none = fast.stream().allMatch(s -> s.runsWithCollisions() == 0);
                int usualRuns = sum(usual, SetSummary::measuredRuns);
                boolean usualClean = usualRuns == 0
                        || (double) sum(usual, SetSummary::runsWithCollisions) / usualRuns < PaperClaims.MAJORITY;
                Verdict v = allMost && usualClean ? Verdict.REPRODUCED : none ? Verdict.NOT_REPRODUCED : Verdict.MIXED;
                String fisher = usual.isEmpty() ? "" : ", Fisher's exact p = " + num(FisherExact.twoSided(
                        sum(fast, SetSummary::runsWithCollisions), sum(fast, SetSummary::measuredRuns),
                        sum(usual, SetSummary::runsWithCollisions), usualRuns), 3);
                List<SetSummary> cells = new ArrayList<>(fast);
                cells.addAll(usual);
                return new Group(v, "runs with a collision at " + PaperClaims.FAST_AT_MOST_MS + " ms or less: "
                        + rate(fast, SetSummary::runsWithCollisions, SetSummary::measuredRuns) + "; from "
                        + (PaperClaims.FAST_AT_MOST_MS + 1) + " to " + PaperClaims.SLOW_ABOVE_MS + " ms: "
                        + rate(usual, SetSummary::runsWithCollisions, SetSummary::measuredRuns) + fisher + " (swept: "
                        + String.join("+", j.sweptTasks()) + ").", cells);
            }, "reproduced if every set whose avoider runs at " + PaperClaims.FAST_AT_MOST_MS + " ms or less has a "
                    + "collision in at least " + pct(PaperClaims.MAJORITY) + " of its runs and the sets from "
                    + (PaperClaims.FAST_AT_MOST_MS + 1) + " to " + PaperClaims.SLOW_ABOVE_MS + " ms in fewer; not "
                    + "reproduced if no run at " + PaperClaims.FAST_AT_MOST_MS + " ms or less collided; mixed otherwise "
                    + "(Fisher's exact test of the two groups in the evidence)");
        }
    }

    /**
     * "The sampling rate needs to be at least two times the fastest input signal ... any behavior that
     * depends upon the laser information should have a period of at most 50 ms."
     */
    static final class SamplingAdvice extends ClaimFamily {

        /** The paper's bound for the tasks that read the 10 Hz laser, ms. */
        static final long LASER_BOUND_MS = 50;

        SamplingAdvice() {
            super("sampling-rate-advice",
                    "Section VII: a task that reads the 10 Hz laser (avoider, occupancy grid) should run at a period of at "
                    + "most 50 ms, twice the laser's rate");
        }

        @Override
        public void judge(Judging j) {
            boolean swept = j.sweptTasks().contains("obstacle") || j.sweptTasks().contains("occupancy");
            perSpeed(this, j, (sets, why) -> {
                if (!swept) {
                    why.add("neither the avoider's nor the occupancy grid's period varies between the sets");
                    return null;
                }
                List<SetSummary> within = onAxis(sets).stream()
                        .filter(s -> s.sweptPeriodMs() <= LASER_BOUND_MS && s.measuredRuns() > 0).toList();
                List<SetSummary> beyond = onAxis(sets).stream().filter(s -> s.sweptPeriodMs() > LASER_BOUND_MS
                        && s.sweptPeriodMs() <= PaperClaims.SLOW_ABOVE_MS && s.measuredRuns() > 0).toList();
                if (within.isEmpty() || beyond.isEmpty()) {
                    why.add("needs sets at " + LASER_BOUND_MS + " ms or less and above " + LASER_BOUND_MS + " up to "
                            + PaperClaims.SLOW_ABOVE_MS + " ms, with runs on the course" + periodsHere(sets));
                    return null;
                }
                double pHits = FisherExact.twoSided(sum(within, SetSummary::runsWithCollisions),
                        sum(within, SetSummary::measuredRuns), sum(beyond, SetSummary::runsWithCollisions),
                        sum(beyond, SetSummary::measuredRuns));
                double pDone = FisherExact.twoSided(sum(within, SetSummary::completed), sum(within, SetSummary::runs),
                        sum(beyond, SetSummary::completed), sum(beyond, SetSummary::runs));
                double hitsWithin = (double) sum(within, SetSummary::runsWithCollisions) / sum(within, SetSummary::measuredRuns);
                double hitsBeyond = (double) sum(beyond, SetSummary::runsWithCollisions) / sum(beyond, SetSummary::measuredRuns);
                double doneWithin = (double) sum(within, SetSummary::completed) / sum(within, SetSummary::runs);
                double doneBeyond = (double) sum(beyond, SetSummary::completed) / sum(beyond, SetSummary::runs);
                boolean advised = pHits < PaperClaims.ALPHA && hitsBeyond > hitsWithin
                        || pDone < PaperClaims.ALPHA && doneBeyond < doneWithin;
                boolean against = pHits < PaperClaims.ALPHA && hitsBeyond < hitsWithin
                        || pDone < PaperClaims.ALPHA && doneBeyond > doneWithin;
                Verdict v = advised && !against ? Verdict.REPRODUCED : against && !advised ? Verdict.NOT_REPRODUCED
                        : advised ? Verdict.MIXED : Verdict.INCONCLUSIVE;
                List<SetSummary> cells = new ArrayList<>(within);
                cells.addAll(beyond);
                return new Group(v, "at " + LASER_BOUND_MS + " ms or less: collided "
                        + rate(within, SetSummary::runsWithCollisions, SetSummary::measuredRuns) + ", completed "
                        + rate(within, SetSummary::completed, SetSummary::runs) + "; above " + LASER_BOUND_MS + " up to "
                        + PaperClaims.SLOW_ABOVE_MS + " ms: collided "
                        + rate(beyond, SetSummary::runsWithCollisions, SetSummary::measuredRuns) + ", completed "
                        + rate(beyond, SetSummary::completed, SetSummary::runs) + "; Fisher's exact p = " + num(pHits, 3)
                        + " (collisions), " + num(pDone, 3) + " (completion) (swept: " + String.join("+", j.sweptTasks())
                        + ").", cells);
            }, "the swept period of the laser's readers at " + LASER_BOUND_MS + " ms or less against above "
                    + LASER_BOUND_MS + " up to " + PaperClaims.SLOW_ABOVE_MS + " ms (beyond that, 'periods above 100 ms' "
                    + "judges): reproduced if the slower group collides more or completes less, by Fisher's exact test at p < "
                    + PaperClaims.ALPHA + "; not reproduced if it does significantly better; inconclusive if neither "
                    + "difference is significant");
        }
    }

    /**
     * "This suggests that available resources may be increased by slowing down the
     * DIJKSTRAPATHPLANNER": the planner can run slower than 100 ms without costing the robot.
     */
    static final class PlannerCanSlow extends ClaimFamily {

        PlannerCanSlow() {
            super("planner-can-slow",
                    "Section VII: the path planner can be slowed (beyond 100 ms) to free resources without costing the "
                    + "robot its course");
        }

        @Override
        public void judge(Judging j) {
            boolean swept = j.sweptTasks().contains("planner");
            boolean alone = j.sweptTasks().equals(List.of("planner"));
            perSpeed(this, j, (sets, why) -> {
                if (!swept) {
                    why.add("the planner's period does not vary between the sets");
                    return null;
                }
                SetSummary base = onAxis(sets).stream()
                        .filter(s -> s.sweptPeriodMs() == Sweep.BASE_PERIOD_MS && s.runs() > 0).findFirst().orElse(null);
                List<SetSummary> slower = onAxis(sets).stream()
                        .filter(s -> s.sweptPeriodMs() > Sweep.BASE_PERIOD_MS && s.runs() > 0).toList();
                if (base == null || slower.isEmpty()) {
                    why.add("needs a set with the planner at " + Sweep.BASE_PERIOD_MS + " ms and one slower"
                            + periodsHere(sets));
                    return null;
                }
                RateInterval baseDone = RateInterval.of(base.completed(), base.runs());
                List<String> parts = new ArrayList<>();
                int kept = 0;
                for (SetSummary s : slower) {
                    RateInterval done = RateInterval.of(s.completed(), s.runs());
                    boolean keeps = !(done.upper() < baseDone.lower());
                    kept += keeps ? 1 : 0;
                    parts.add(s.sweptPeriodMs() + " ms completed " + done.text() + ", misses of all four "
                            + num(s.misses().get(ExperimentSummary.ALL_TASKS).missPct(), 2) + "%"
                            + (keeps ? "" : " (fewer completed)"));
                }
                Verdict v = kept == slower.size() ? Verdict.REPRODUCED
                        : alone ? (kept == 0 ? Verdict.NOT_REPRODUCED : Verdict.MIXED) : Verdict.INCONCLUSIVE;
                List<SetSummary> cells = new ArrayList<>(slower);
                cells.add(base);
                return new Group(v, "at " + Sweep.BASE_PERIOD_MS + " ms completed " + baseDone.text() + ", misses of all "
                        + "four " + num(base.misses().get(ExperimentSummary.ALL_TASKS).missPct(), 2) + "%; " + String.join("; ",
                        parts) + (alone ? "" : " (swept with the planner: " + String.join("+", j.sweptTasks())
                        + ", so a loss cannot be pinned on the planner)") + ".", cells);
            }, "every set with the planner slower than " + Sweep.BASE_PERIOD_MS + " ms against the set at "
                    + Sweep.BASE_PERIOD_MS + " ms: the robot's course is kept if the 95% Wilson interval of the completion "
                    + "rate does not lie wholly below the " + Sweep.BASE_PERIOD_MS + " ms set's; reproduced if every slower set "
                    + "keeps it; where the planner is swept alone, not reproduced if none does and mixed otherwise; where "
                    + "other tasks are slowed with it, inconclusive if some set loses it");
        }
    }
}
