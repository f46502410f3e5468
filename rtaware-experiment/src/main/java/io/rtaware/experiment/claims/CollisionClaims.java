package io.rtaware.experiment.claims;

import static io.rtaware.experiment.claims.Judging.num;
import static io.rtaware.experiment.claims.Judging.onAxis;
import static io.rtaware.experiment.claims.Judging.pct;
import static io.rtaware.experiment.claims.Judging.periodsHere;

import io.rtaware.experiment.Decimals;
import io.rtaware.experiment.ExperimentSummary;
import io.rtaware.experiment.ExperimentSummary.Misses;
import io.rtaware.experiment.ExperimentSummary.SetSummary;
import io.rtaware.experiment.RunResult;
import io.rtaware.experiment.stats.RateInterval;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

/** The paper's claims about periods too slow and too fast for the robot (Section VII), judged per top speed. */
final class CollisionClaims {

    private CollisionClaims() {
    }

    /** "Experiments were also run with periods larger than 100 ms ... the robot would hit the wall as well as obstacles." */
    static final class SlowHits extends ClaimFamily {

        SlowHits() {
            super("slow-hits",
                    "periods above 100 ms: the robot hits walls and obstacles");
        }

        @Override
        public void judge(Judging j) {
            j.bySpeed().forEach((speed, group) -> judge(j, group, j.atSpeed(j.course(), speed)));
        }

        private void judge(Judging j, List<SetSummary> group, Scope scope) {
            List<SetSummary> above = onAxis(group).stream()
                    .filter(s -> s.sweptPeriodMs() > PaperClaims.SLOW_ABOVE_MS && s.measuredRuns() > 0).toList();
            if (above.isEmpty()) {
                j.unjudged(this, scope, "no set with a period above " + PaperClaims.SLOW_ABOVE_MS
                        + " ms and a run that ended on the course" + periodsHere(group));
                return;
            }
            List<SetSummary> below = onAxis(group).stream().filter(s -> s.sweptPeriodMs() <= PaperClaims.SLOW_ABOVE_MS)
                    .toList();
            int belowRuns = below.stream().mapToInt(SetSummary::measuredRuns).sum();
            int belowHits = below.stream().mapToInt(SetSummary::runsWithCollisions).sum();
            boolean baselineClean = belowRuns == 0 || (double) belowHits / belowRuns < PaperClaims.MAJORITY;
            boolean allMost = above.stream().allMatch(s -> s.collisionRate() >= PaperClaims.MAJORITY);
            boolean none = above.stream().allMatch(s -> s.runsWithCollisions() == 0);
            Verdict v = allMost && baselineClean ? Verdict.REPRODUCED : none ? Verdict.NOT_REPRODUCED : Verdict.MIXED;
            List<String> parts = new ArrayList<>();
            for (SetSummary s : above) {
                parts.add(s.name() + " (" + s.sweptPeriodMs() + " ms): " + s.collisions95().text() + " runs collided ("
                        + s.collisions() + " collisions), " + s.completed() + " of " + s.runs() + " completed"
                        + (s.nearMisses() == null ? "" : ", " + s.runsWithNearMisses() + " with a near miss"));
            }
            String evidence = String.join("; ", parts) + ". At or below " + PaperClaims.SLOW_ABOVE_MS + " ms: "
                    + (belowRuns == 0 ? "no runs" : RateInterval.of(belowHits, belowRuns).text() + " runs collided") + ". "
                    + ReactionRule.firstCollision(group)
                            .map(s -> "Shortest period with a collision: " + s.sweptPeriodMs() + " ms (" + s.name() + ").")
                            .orElse("No run collided at any period.")
                    + ReactionRule.comparedWithCollisions(group);
            j.judged(this, scope, v, evidence, "reproduced if every set above " + PaperClaims.SLOW_ABOVE_MS
                    + " ms has a collision in at least " + pct(PaperClaims.MAJORITY) + " of its runs and the sets at or below "
                    + PaperClaims.SLOW_ABOVE_MS + " ms (if any) in fewer than " + pct(PaperClaims.MAJORITY)
                    + "; not reproduced if no run above " + PaperClaims.SLOW_ABOVE_MS + " ms collided; mixed otherwise",
                    Stream.concat(above.stream(), below.stream()).toList(), SetSummary::measuredRuns);
        }
    }

    /** "Experiments were also run with periods of 5 ms and less, which resulted in the robot ... locking up." */
    static final class FastLocksUp extends ClaimFamily {

        FastLocksUp() {
            super("fast-locks-up",
                    "periods of 5 ms or less: the system locks up");
        }

        @Override
        public void judge(Judging j) {
            j.bySpeed().forEach((speed, group) -> judge(j, group, j.atSpeed(Scope.PAPER, speed)));
        }

        private void judge(Judging j, List<SetSummary> group, Scope scope) {
            List<SetSummary> fastSets = onAxis(group).stream()
                    .filter(s -> s.sweptPeriodMs() <= PaperClaims.FAST_AT_MOST_MS).toList();
            if (fastSets.isEmpty()) {
                j.unjudged(this, scope, "no set with a period of " + PaperClaims.FAST_AT_MOST_MS + " ms or less"
                        + periodsHere(group));
                return;
            }
            boolean allMost = fastSets.stream().allMatch(s -> errors(s) >= PaperClaims.MAJORITY * s.runs());
            boolean none = fastSets.stream().allMatch(s -> errors(s) == 0);
            // Under a CPU quota the starved machine is emulated, so no lock-up speaks against the paper.
            Double quota = j.cpuQuota();
            Verdict v = allMost ? Verdict.REPRODUCED
                    : none ? (quota != null ? Verdict.NOT_REPRODUCED : Verdict.NOT_COMPARABLE) : Verdict.MIXED;
            List<String> parts = new ArrayList<>();
            if (quota != null) {
                parts.add("each run's JVM (controller and built-in server) under a quota of " + Decimals.plain(quota)
                        + " CPU (--cpu-limit), the paper's one starved computer emulated");
            }
            for (SetSummary s : fastSets) {
                parts.add(robot(s));
            }
            onAxis(group).stream().filter(s -> s.sweptPeriodMs() == PaperClaims.SLOW_ABOVE_MS).findFirst()
                    .ifPresent(s -> parts.add("for comparison, " + robot(s)));
            j.judged(this, scope, v, String.join("; ", parts) + "." + (v == Verdict.NOT_COMPARABLE
                    ? " " + PaperClaims.LOCK_UP_MECHANISM : ""), "a run 'locks up' when its process fails or leaves no "
                    + "report (outcome error); reproduced if at least " + pct(PaperClaims.MAJORITY) + " of the runs of "
                    + "every set at " + PaperClaims.FAST_AT_MOST_MS + " ms or less lock up; if none does, not reproduced "
                    + "when the runs had a CPU quota (--cpu-limit: the starved machine emulated), else not comparable (the "
                    + "paper's lock-up came from a starved machine that a run without a quota does not have); mixed otherwise",
                    fastSets, SetSummary::runs);
        }

        private static String robot(SetSummary s) {
            Misses all = s.misses().get(ExperimentSummary.ALL_TASKS);
            String skipped = all.skipped() == null ? "skipped releases not recorded"
                    : all.skipped() + " releases skipped (" + pct(all.releases() == 0 ? 0
                    : (double) all.skipped() / all.releases()) + " of " + all.releases() + ")";
            return s.name() + " (" + s.sweptPeriodMs() + " ms): " + errors(s) + " of " + s.runs() + " runs locked up, "
                    + s.completed() + " completed, outcomes " + s.outcomes() + ", " + s.runsWithCollisions() + " of "
                    + s.measuredRuns() + " collided, misses " + num(all.missPct(), 2) + "% of all four tasks' releases, "
                    + skipped + (s.runTimeS().mean() == null ? "" : ", mean run time " + num(s.runTimeS().mean(), 1) + " s");
        }

        private static int errors(SetSummary s) {
            return s.outcomes().getOrDefault(RunResult.ERROR, 0);
        }
    }
}
