package io.rtaware.experiment.claims;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.experiment.ExperimentProfile;
import io.rtaware.experiment.ExperimentSets;
import io.rtaware.experiment.ExperimentSummary;
import io.rtaware.experiment.PeriodSet;
import io.rtaware.experiment.ResultsCsv;
import io.rtaware.experiment.RunConditions;
import io.rtaware.experiment.RunResult;
import io.rtaware.experiment.TaskResult;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.ToDoubleBiFunction;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Verdicts on the paper's claims from synthetic results.csv rows, one test per verdict and claim. */
class PaperClaimsTest {

    @TempDir
    Path dir;

    private static final RunConditions CONDITIONS = new RunConditions("paper-room", 10, 1, null);

    /** How a synthetic run turns out. */
    private interface Outcome {
        /** @return outcome, run time, distance, collisions for set s (period p) run r */
        Object[] of(PeriodSet s, long periodMs, int run);
    }

    /** The obstacle task's largest safe period in every synthetic run's advice, ms (0: the rule finds none). */
    private double obstacleBoundMs = 250.0;

    /** Every synthetic run's p99 execution time per task, us. */
    private java.util.function.ToDoubleFunction<String> execUs = task -> 50;

    /** The world seed of run 1 of each set: with the same for every set, run j of every set shares seed j. */
    private java.util.function.IntToLongFunction firstSeed = set -> 1;

    private List<RunResult> rows(List<PeriodSet> sets, int runs, Outcome outcome, ToDoubleBiFunction<String, Long> missPct) {
        List<RunResult> rows = new ArrayList<>();
        for (int run = 1; run <= runs; run++) {
            for (int i = 0; i < sets.size(); i++) {
                PeriodSet s = sets.get(i);
                long period = s.periodsMs().values().stream().mapToLong(Long::longValue).max().orElseThrow();
                if (s.periodsMs().get("obstacle") != 100) {
                    period = s.periodsMs().get("obstacle");
                }
                Object[] o = outcome.of(s, period, run);
                Map<String, TaskResult> tasks = new LinkedHashMap<>();
                if (!RunResult.ERROR.equals(o[0])) {
                    for (String t : PeriodSet.TASKS) {
                        double pct = missPct.applyAsDouble(t, s.periodsMs().get(t));
                        long misses = Math.round(pct * 100);
                        tasks.put(t, new TaskResult(10_000, misses, 100.0 * misses / 10_000, 0, execUs.applyAsDouble(t), misses / 2,
                                "obstacle".equals(t) ? obstacleBoundMs : null));
                    }
                }
                RunConditions conditions = new RunConditions(CONDITIONS.scenario(), CONDITIONS.timeScale(),
                        firstSeed.applyAsLong(i + 1), null);
                rows.add(new RunResult(i + 1, run, s, conditions, (String) o[0], (double) o[1], (double) o[2], 20.0,
                        RunResult.ERROR.equals(o[0]) ? null : (Integer) o[3], 4, 4, tasks, Map.of()));
            }
        }
        // Through results.csv, as the report reads them.
        Path csv = dir.resolve("results-" + System.nanoTime() + ".csv");
        try {
            for (RunResult r : rows) {
                ResultsCsv.append(csv, r);
            }
            return ResultsCsv.read(csv);
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    private static ExperimentSummary summary(List<RunResult> rows) {
        return ExperimentSummary.of(rows, ExperimentProfile.fromResults(rows));
    }

    private static Claim claim(ExperimentSummary s, String id) {
        return s.claims().stream().filter(c -> c.id().equals(id)).findFirst()
                .orElseThrow(() -> new AssertionError(id + " not evaluated: " + s.claimsNotEvaluated()));
    }

    private static RuleVerdict rule(ExperimentSummary s, String id) {
        return s.rules().stream().filter(r -> r.id().equals(id)).findFirst()
                .orElseThrow(() -> new AssertionError(id + " not among the rules: " + s.rules()));
    }

    private static boolean notEvaluated(ExperimentSummary s, String id) {
        return s.claimsNotEvaluated().stream().anyMatch(n -> n.id().equals(id));
    }

    private static Object[] completed(double runTime) {
        return new Object[] {"completed", runTime, 0.3, 0};
    }

    private static final ToDoubleBiFunction<String, Long> FALLING = (task, period) -> 50.0 / period;

    @Test
    void slowPeriodsCollideReproducedMixedAndNot() {
        List<PeriodSet> sweep = ExperimentSets.resolve("sweep-obstacle");
        ExperimentSummary reproduced = summary(rows(sweep, 4, (s, p, r) -> p > 100
                ? new Object[] {"stuck", 120.0, 3.0, r <= 3 ? 2 : 0} : completed(230), FALLING));
        Claim c = claim(reproduced, "slow-hits");
        assertEquals(Verdict.REPRODUCED, c.verdict(), c.evidence());
        assertTrue(c.evidence().contains("obstacle 200 ms (200 ms): 3 of 4 (75 %, 95 % CI 30-95 %) runs collided (6 collisions),"
                + " 0 of 4 completed"),
                c.evidence());
        assertTrue(c.evidence().contains("At or below 100 ms: 0 of 20 (0 %, 95 % CI 0-16 %) runs collided"), c.evidence());
        assertTrue(c.evidence().contains("Shortest period with a collision: 200 ms"), c.evidence());
        assertTrue(c.evidence().contains("Reaction rule (the runs' advice): largest safe period of obstacle 250.0 ms (mean "
                + "over 8 set(s)); the shortest period with a collision, 200 ms, is 0.80 x that bound."), c.evidence());

        ExperimentSummary mixed = summary(rows(sweep, 4, (s, p, r) -> p == 800 && r == 1
                ? new Object[] {"completed", 240.0, 0.3, 1} : completed(230), FALLING));
        assertEquals(Verdict.MIXED, claim(mixed, "slow-hits").verdict());

        ExperimentSummary clean = summary(rows(sweep, 2, (s, p, r) -> completed(230), FALLING));
        Claim not = claim(clean, "slow-hits");
        assertEquals(Verdict.NOT_REPRODUCED, not.verdict());
        assertTrue(not.evidence().contains("No run collided at any period."), not.evidence());

        // Collisions everywhere: not the period's doing.
        ExperimentSummary everywhere = summary(rows(sweep, 2, (s, p, r) -> new Object[] {"completed", 230.0, 0.3, 1}, FALLING));
        assertEquals(Verdict.MIXED, claim(everywhere, "slow-hits").verdict());
    }

    @Test
    void theReactionRuleIsRtawaresOwnAndJudgedByWhereCollisionsBeginAgainstItsBound() {
        // every run's advice gives the obstacle task a largest safe period of 250 ms
        List<PeriodSet> sweep = ExperimentSets.resolve("sweep-obstacle");
        ExperimentSummary nearSummary = summary(rows(sweep, 2, (s, p, r) -> p >= 300
                ? new Object[] {"stuck", 120.0, 3.0, 1} : completed(230), FALLING));
        RuleVerdict near = rule(nearSummary, "reaction-rule-bound");
        assertEquals(RuleVerdict.HOLDS, near.verdict(), near.evidence());
        // the sweep's periods above 200 ms: 400 ms is the first with collisions
        assertEquals("largest safe period 250.0 ms; the shortest period with a collision is 400 ms (obstacle 400 ms, 2 of "
                + "2 runs), 1.60 x the bound.", near.evidence());
        assertTrue(nearSummary.claims().stream().noneMatch(c -> c.id().startsWith("reaction-rule-bound")),
                "rtaware's rule is not among the paper's claims: " + nearSummary.claims());
        assertTrue(!near.rule().contains("Paper") && near.rule().startsWith("rtaware's reaction rule"), near.rule());
        RuleVerdict unsafe = rule(summary(rows(sweep, 2, (s, p, r) -> p >= 200
                ? new Object[] {"stuck", 120.0, 3.0, 1} : completed(230), FALLING)), "reaction-rule-bound");
        assertEquals(RuleVerdict.FAILS, unsafe.verdict(), "collisions below the bound: " + unsafe.evidence());
        RuleVerdict cautious = rule(summary(rows(sweep, 2, (s, p, r) -> completed(230), FALLING)), "reaction-rule-bound");
        assertEquals(RuleVerdict.FAILS, cautious.verdict(), "none up to 800 ms, 3.2 x the bound: " + cautious.evidence());
        RuleVerdict belowTheBound = rule(summary(rows(ExperimentSets.resolve("paper"), 2, (s, p, r) -> completed(230),
                FALLING)), "reaction-rule-bound");
        assertEquals(RuleVerdict.NOT_EVALUATED, belowTheBound.verdict(), "periods of 10-100 ms against a 250 ms bound "
                + "and no collision agree with the rule without testing it: " + belowTheBound.evidence());
        List<RunResult> corridor = rows(sweep, 2, (s, p, r) -> completed(230), FALLING).stream()
                .map(r -> new RunResult(r.set(), r.run(), r.periods(), new RunConditions("corridor", 10, 1, null),
                        r.outcome(), r.runTimeS(), r.distanceToFinishM(), r.distanceTravelledM(), r.collisions(),
                        r.waypointsReached(), r.waypointsTotal(), r.tasks(), r.mediatorCycles(), 0.02, 1L)).toList();
        ExperimentSummary onCorridor = summary(corridor);
        assertTrue(claim(onCorridor, "slow-hits-on-corridor").claim().endsWith(" on corridor"),
                "another course is named in the claim: " + onCorridor.claims());
        assertTrue(claim(onCorridor, "slow-hits-on-corridor").evidence().contains("2 with a near miss"),
                "near misses in the evidence");
        assertEquals(RuleVerdict.FAILS, rule(onCorridor, "reaction-rule-bound-on-corridor").verdict());
    }

    /**
     * Issue 38: a course named by a path (the documented {@code --scenario FILE}) lost the
     * experiment's report: claim ids were parsed back from the claim's words, which held the path.
     */
    @Test
    void aCourseNamedByAPathKeepsThePathInItsWordsAndItsFileNameInTheId() throws Exception {
        String course = "/data/courses/hall v2.yaml";
        List<RunResult> rows = rows(ExperimentSets.resolve("paper"), 2, (s, p, r) -> completed(230), FALLING).stream()
                .map(r -> new RunResult(r.set(), r.run(), r.periods(), new RunConditions(course, 10, 1, null),
                        r.outcome(), r.runTimeS(), r.distanceToFinishM(), r.distanceTravelledM(), r.collisions(),
                        r.waypointsReached(), r.waypointsTotal(), r.tasks(), r.mediatorCycles())).toList();
        ExperimentSummary s = summary(rows);
        Map<String, String> wordsById = new LinkedHashMap<>();
        s.claims().forEach(c -> wordsById.put(c.id(), c.claim()));
        s.claimsNotEvaluated().forEach(n -> wordsById.put(n.id(), n.claim()));
        assertEquals("periods above 100 ms: the robot hits walls and obstacles on " + course,
                wordsById.get("slow-hits-on-hall-v2"), "the course is named in the claim: " + wordsById);
        assertTrue(wordsById.containsKey("table1-set1-faster"), "claims without a course keep their ids: " + wordsById);
        String json = io.rtaware.core.report.ReportDocument.mapper().writeValueAsString(s);
        assertTrue(json.contains("\"id\" : \"slow-hits-on-hall-v2\""), "the summary is written with the ids");
    }

    /** Issue 35: where the rule finds no safe period it names no bound, so collisions cannot "reproduce" it. */
    @Test
    void whereTheRuleFindsNoSafePeriodItIsNotEvaluatedWithTheReason() {
        obstacleBoundMs = 0; // "cannot react in time at any period"
        List<PeriodSet> sweep = ExperimentSets.resolve("sweep-obstacle");
        RuleVerdict everywhere = rule(summary(rows(sweep, 3, (s, p, r) -> r == 1
                ? new Object[] {"stuck", 120.0, 3.0, 1} : completed(230), FALLING)), "reaction-rule-bound");
        assertEquals(RuleVerdict.NOT_EVALUATED, everywhere.verdict(), everywhere.evidence());
        assertTrue(everywhere.evidence().startsWith("the rule finds no safe period here"), everywhere.evidence());
        assertTrue(everywhere.evidence().contains("5 ms 1 of 3 (33 %, 95 % CI 6-79 %)"), everywhere.evidence());
        assertEquals("", everywhere.judgedBy());
        RuleVerdict never = rule(summary(rows(sweep, 3, (s, p, r) -> completed(230), FALLING)), "reaction-rule-bound");
        assertEquals(RuleVerdict.NOT_EVALUATED, never.verdict(), never.evidence());
        Claim slow = claim(summary(rows(sweep, 3, (s, p, r) -> completed(230), FALLING)), "slow-hits");
        assertTrue(slow.evidence().contains("no period of obstacle is safe"), slow.evidence());
    }

    @Test
    void fastPeriodsLockUpReproducedMixedAndNot() {
        List<PeriodSet> sweep = ExperimentSets.resolve("sweep-all");
        ExperimentSummary locked = summary(rows(sweep, 2, (s, p, r) -> p <= 5
                ? new Object[] {RunResult.ERROR, Double.NaN, Double.NaN, null} : completed(230), FALLING));
        assertEquals(Verdict.REPRODUCED, claim(locked, "fast-locks-up").verdict());

        ExperimentSummary half = summary(rows(sweep, 3, (s, p, r) -> p <= 5 && r == 1
                ? new Object[] {RunResult.ERROR, Double.NaN, Double.NaN, null} : completed(230), FALLING));
        assertEquals(Verdict.MIXED, claim(half, "fast-locks-up").verdict());

        ExperimentSummary running = summary(rows(sweep, 2, (s, p, r) -> p <= 5
                ? new Object[] {"timeout", 360.0, 4.0, 0} : completed(230), FALLING));
        Claim c = claim(running, "fast-locks-up");
        assertEquals(Verdict.NOT_COMPARABLE, c.verdict(), "no lock-up here cannot speak against the paper's mechanism");
        assertTrue(c.evidence().contains(PaperClaims.LOCK_UP_MECHANISM), c.evidence());
        // what happens to the robot, from the data: 10 % of releases missed at 5 ms, half of them skipped
        assertTrue(c.evidence().contains("all 5 ms (5 ms): 0 of 2 runs locked up, 0 completed, outcomes {timeout=2}"),
                c.evidence());
        assertTrue(c.evidence().contains("misses 10.00% of all four tasks' releases, 4000 releases skipped (5.0% of 80000)"),
                c.evidence());
        assertTrue(c.evidence().contains("for comparison, all 100 ms (100 ms): 0 of 2 runs locked up, 2 completed"),
                c.evidence());

        // The same runs on the emulated starved machine (--cpu-limit 1): no lock-up now speaks against the paper.
        List<RunResult> starved = rows(sweep, 2, (s, p, r) -> p <= 5
                ? new Object[] {"timeout", 360.0, 4.0, 0} : completed(230), FALLING).stream()
                .map(r -> new RunResult(r.set(), r.run(), r.periods(), r.conditions().withCpuLimit(1.0), r.outcome(),
                        r.runTimeS(), r.distanceToFinishM(), r.distanceTravelledM(), r.collisions(),
                        r.waypointsReached(), r.waypointsTotal(), r.tasks(), r.mediatorCycles(), r.minClearanceM(),
                        r.nearMisses(), r.machine())).toList();
        Claim onQuota = claim(summary(starved), "fast-locks-up");
        assertEquals(Verdict.NOT_REPRODUCED, onQuota.verdict(), onQuota.evidence());
        assertTrue(onQuota.evidence().startsWith("each run's JVM (controller and built-in server) under a quota of 1 CPU"),
                onQuota.evidence());
        assertFalse(onQuota.evidence().contains(PaperClaims.LOCK_UP_MECHANISM), onQuota.evidence());
        assertTrue(onQuota.judgedOn().endsWith(", under 1 CPU"), onQuota.judgedOn());
    }

    @Test
    void missesFallReproducedMixedAndNot() {
        List<PeriodSet> sweep = ExperimentSets.resolve("sweep-all");
        Claim falls = claim(summary(rows(sweep, 1, (s, p, r) -> completed(230), FALLING)), "misses-fall");
        assertEquals(Verdict.REPRODUCED, falls.verdict());
        assertTrue(falls.evidence().contains("planner: rho -1.00 over 8 sets, 10.00% at 5 ms, 0.06% at 800 ms"),
                falls.evidence());

        Claim mixed = claim(summary(rows(sweep, 1, (s, p, r) -> completed(230),
                (task, period) -> "planner".equals(task) ? period / 100.0 : 50.0 / period)), "misses-fall");
        assertEquals(Verdict.MIXED, mixed.verdict(), mixed.evidence());

        Claim flat = claim(summary(rows(sweep, 1, (s, p, r) -> completed(230), (task, period) -> 0)), "misses-fall");
        assertEquals(Verdict.NOT_REPRODUCED, flat.verdict());
        assertTrue(flat.evidence().contains("undefined (the same miss % everywhere)"), flat.evidence());
    }

    @Test
    void tableOneAndTwoClaimsOnThePaperSets() {
        List<PeriodSet> paper = ExperimentSets.paper();
        // Set 1 fast, Sets 4 and 5 slow; Set 3 fastest but widest? No: Set 1 fastest here.
        double[][] times = {{250, 251, 252}, {270, 262, 278}, {262, 270, 278}, {280, 281, 282}, {280, 282, 284}};
        List<RunResult> rows = rows(paper, 3, (s, p, r) -> {
            int set = paper.indexOf(s);
            return new Object[] {"completed", times[set][r - 1], 2.0 + 0.1 * ((set + r) % 3), 0};
        }, (task, period) -> ("planner".equals(task) ? 40 : "occupancy".equals(task) ? 30 : "waypoint".equals(task) ? 20 : 5)
                / (double) period);
        ExperimentSummary s = summary(rows);
        Claim t1 = claim(s, "table1-set1-faster");
        assertEquals(Verdict.REPRODUCED, t1.verdict(), t1.evidence());
        assertEquals(Verdict.NOT_REPRODUCED, claim(s, "table1-set3-fastest-widest").verdict());
        assertEquals(Verdict.REPRODUCED, claim(s, "fig7-planner-most").verdict());
        Claim same = claim(s, "tables-almost-identical");
        assertEquals(Verdict.MIXED, same.verdict(), same.evidence());
        Claim distance = claim(s, "table2-no-difference");
        // No pair differs, but with 3 runs a set the tests detect only differences of about 0.3 m,
        // larger than the paper's differences of the set means (0.01 to 0.28 m).
        assertEquals(Verdict.INCONCLUSIVE, distance.verdict(), distance.evidence());
        assertTrue(distance.evidence().contains("too weak to see the paper's differences: Set 1 vs Set 2 detects"),
                distance.evidence());
        Claim misses = claim(s, "fig8-set1-most-misses");
        assertEquals(Verdict.REPRODUCED, misses.verdict(), "all tasks at 10 ms miss most: " + misses.evidence());
        Claim spread = claim(s, "table1-spread-twice");
        // SDs: Set 1 1, Set 2 8, Set 3 8, Set 4 1, Set 5 2: (8 + 8) / 2 over (1 + 1 + 2) / 3 = 6
        assertEquals(Verdict.REPRODUCED, spread.verdict(), spread.evidence());
        assertTrue(spread.evidence().contains("ratio 6.00 (paper: 10.79 s and 6.03 s, ratio 1.79)"), spread.evidence());
        Claim verge = claim(s, "table1-verge");
        assertTrue(verge.evidence().contains("Set 2 vs Set 4: confidence"), verge.evidence());

        // Set 1 slowest: the Set 1 claim fails both ways.
        List<RunResult> reversed = rows(paper, 3, (x, p, r) -> completed(paper.indexOf(x) == 0 ? 300 + r : 250 + r),
                (task, period) -> 1);
        assertEquals(Verdict.NOT_REPRODUCED, claim(summary(reversed), "table1-set1-faster").verdict());
    }

    @Test
    void noDistanceDifferenceWithEnoughPowerIsReproduced() {
        List<PeriodSet> paper = ExperimentSets.paper();
        // 10 runs a set, distances within +-0.001 m: the tests detect differences far below the paper's
        List<RunResult> rows = rows(paper, 10, (s, p, r) -> new Object[] {"completed", 250.0 + r, 2.0 + 0.001 * (r % 3), 0},
                (task, period) -> 1);
        Claim distance = claim(summary(rows), "table2-no-difference");
        assertEquals(Verdict.REPRODUCED, distance.verdict(), distance.evidence());
    }

    @Test
    void everyTimingClaimOfThePaperIsJudgedOrListedWithAReason() {
        ExperimentSummary s = summary(rows(ExperimentSets.paper(), 2, (x, p, r) -> completed(250 + r), (task, period) -> 1));
        List<String> all = new java.util.ArrayList<>();
        s.claims().forEach(c -> all.add(c.id()));
        s.claimsNotEvaluated().forEach(c -> {
            assertTrue(!c.reason().isBlank(), c.id());
            all.add(c.id());
        });
        for (String claim : PaperClaims.familyIds()) {
            assertTrue(all.contains(claim), "claim listed: " + claim + " in " + all);
        }
    }

    @Test
    void claimsWithoutTheirDataAreListedAsNotEvaluatedWithTheReason() {
        List<PeriodSet> two = List.of(PeriodSet.of("a", 20, 20, 20, 20), PeriodSet.of("b", 50, 50, 50, 50));
        ExperimentSummary s = summary(rows(two, 2, (x, p, r) -> completed(230), FALLING));
        assertTrue(notEvaluated(s, "slow-hits"));
        assertTrue(notEvaluated(s, "fast-locks-up"));
        assertTrue(notEvaluated(s, "misses-fall"), "two periods are no trend");
        assertTrue(notEvaluated(s, "table1-set1-faster"));
        assertTrue(s.claimsNotEvaluated().stream().anyMatch(n -> n.reason().contains("(periods here: 20 ms, 50 ms)")),
                s.claimsNotEvaluated().toString());
        assertTrue(s.claimsNotEvaluated().stream().anyMatch(n -> n.reason().contains("Set 1 (10/10/10/10 ms")),
                s.claimsNotEvaluated().toString());
        assertEquals(List.of(), s.claims().stream().filter(c -> c.claim().startsWith("Table I t")).toList());
    }

    @Test
    void theReportStatesTheClaimsAndDrawsTheSweepAgainstPeriodAndSpeed() throws Exception {
        Path f = dir.resolve("grid.yaml");
        java.nio.file.Files.writeString(f, "sweep:\n  tasks: [obstacle]\n  periods_ms: [5, 100, 800]\n"
                + "  top_speed_mps: [0.1, 0.6]\n");
        List<RunResult> rows = rows(ExperimentSets.resolve(f.toString()), 2, (x, p, r) -> x.topSpeedMps() * p > 50
                ? new Object[] {"stuck", 90.0 + r, 2.5, 2} : completed(200 + 10 * r + p / 100.0), FALLING);
        Path out = java.nio.file.Files.createDirectories(dir.resolve("report"));
        for (RunResult r : rows) {
            ResultsCsv.append(out.resolve(ResultsCsv.FILE_NAME), r);
        }
        ExperimentSummary s = io.rtaware.experiment.report.ExperimentReport.render(out,
                io.rtaware.experiment.report.MapBackground.none(), true);
        for (String name : List.of("sweep-rates", "sweep-runtime", "sweep-distance", "sweep-misses", "speed-rates",
                "speed-runtime", "speed-distance", "speed-misses")) {
            assertTrue(java.nio.file.Files.size(out.resolve(name + ".png")) > 5000, name);
            assertTrue(java.nio.file.Files.exists(out.resolve(name + ".svg")), name);
        }
        String md = java.nio.file.Files.readString(out.resolve("report.md"));
        assertTrue(md.contains("## Claims of the paper"), md);
        assertTrue(md.contains("| periods above 100 ms: the robot hits walls and obstacles (at 0.1 m/s) | **reproduced** (from fewer "
                + "than 5 runs per cell (fewest 2)) | reproduced | "), md);
        assertTrue(md.contains("| periods above 100 ms: the robot hits walls and obstacles (at 0.6 m/s) | **mixed** (from fewer than 5 "
                + "runs per cell (fewest 2)) | mixed | "), md);
        assertTrue(md.contains("| 800 | obstacle 800 ms at 0.1 m/s | 0.1 | 0% | 100% |"), md);
        assertTrue(md.contains("![Completed and collided runs against the period (log axis)](sweep-rates.png)"), md);
        com.fasterxml.jackson.databind.JsonNode json = io.rtaware.core.report.ReportDocument.mapper()
                .readTree(out.resolve("summary.json").toFile());
        assertEquals(s.claims().size(), json.get("claims").size());
        assertEquals("reproduced", json.get("claims").get(0).get("verdict").asText(), json.get("claims").toString());
        assertEquals("mixed", json.get("claims").get(1).get("verdict").asText(), json.get("claims").toString());
        assertTrue(json.get("claims").get(0).has("evidence"));
        assertTrue(json.get("claims_not_evaluated").size() > 0);
        assertEquals(1.0, json.get("sets").get(0).get("completion_rate").asDouble(), 1e-9);
        assertEquals(0.0, json.get("sets").get(2).get("completion_rate").asDouble(), 1e-9);
        assertEquals(1.0, json.get("sets").get(2).get("collision_rate").asDouble(), 1e-9);
    }

    @Test
    void slowAndFastArePerTopSpeedWhenSpeedIsSwept() throws Exception {
        Path f = dir.resolve("grid.yaml");
        java.nio.file.Files.writeString(f, "sweep:\n  tasks: [obstacle]\n  periods_ms: [5, 100, 400]\n  top_speed_mps: [0.1, 0.5]\n");
        List<PeriodSet> grid = ExperimentSets.resolve(f.toString());
        ExperimentSummary s = summary(rows(grid, 2, (x, p, r) -> x.topSpeedMps() > 0.2 && p > 100
                ? new Object[] {"stuck", 50.0, 3.0, 1} : completed(230), FALLING));
        assertEquals(Verdict.NOT_REPRODUCED, claim(s, "slow-hits@0.1mps").verdict());
        assertEquals(Verdict.REPRODUCED, claim(s, "slow-hits@0.5mps").verdict());
        assertEquals(Verdict.NOT_COMPARABLE, claim(s, "fast-locks-up@0.5mps").verdict());
        assertEquals("slow-hits@0.5mps", claim(s, "slow-hits@0.5mps").id());
    }

    /** Issue 35: a verdict that leaving runs out decides is shown with the verdict on all runs, as fragile. */
    @Test
    void exclusionThatDecidesAVerdictIsMarkedFragileWithTheVerdictOnAllRuns() {
        List<PeriodSet> sweep = ExperimentSets.resolve("sweep-obstacle");
        // runs 1 and 2 collide above 100 ms; leaving them out (as if busy) leaves no collision there
        List<RunResult> all = rows(sweep, 4, (s, p, r) -> p > 100 && r <= 2
                ? new Object[] {"stuck", 120.0, 3.0, 1} : completed(230), FALLING);
        List<RunResult> used = all.stream().filter(r -> r.run() >= 3).toList();
        ExperimentSummary s = ExperimentSummary.of(used, all, ExperimentProfile.fromResults(all),
                io.rtaware.experiment.ExperimentConditions.of(all, true));
        Claim slow = claim(s, "slow-hits");
        assertEquals(Verdict.NOT_REPRODUCED, slow.verdict(), slow.evidence());
        assertEquals("reproduced", slow.verdictAllRuns());
        assertTrue(slow.fragile());
        assertTrue(slow.caveats().startsWith("fragile: on all runs, busy ones included, reproduced"), slow.caveats());
        Claim falls = claim(s, "misses-fall");
        assertEquals("reproduced", falls.verdictAllRuns());
        assertEquals(false, falls.fragile(), "the same verdict either way");
        ExperimentSummary allUsed = ExperimentSummary.of(all, all, ExperimentProfile.fromResults(all),
                io.rtaware.experiment.ExperimentConditions.of(all, true));
        assertEquals(false, claim(allUsed, "slow-hits").fragile(), "nothing left out, nothing fragile");
    }

    /** Issue 35: a verdict from fewer than five runs in some set says so, in a field and in words. */
    @Test
    void aVerdictFromFewerThanFiveRunsPerCellSaysSo() {
        List<PeriodSet> sweep = ExperimentSets.resolve("sweep-obstacle");
        Claim four = claim(summary(rows(sweep, 4, (s, p, r) -> completed(230), FALLING)), "slow-hits");
        assertEquals(4, four.fewestRunsPerCell());
        assertTrue(four.smallSample());
        assertTrue(four.caveats().contains("from fewer than 5 runs per cell (fewest 4)"), four.caveats());
        Claim five = claim(summary(rows(sweep, 5, (s, p, r) -> completed(230), FALLING)), "slow-hits");
        assertEquals(5, five.fewestRunsPerCell());
        assertEquals(false, five.smallSample());
        assertEquals("", five.caveats());
    }

    /** Issue 35: two experiments under the same course, speed and swept tasks that disagree say so in RESULTS.md. */
    @Test
    void resultsMarkdownNamesAnotherExperimentThatDisagreesUnderTheSameConditions() {
        List<PeriodSet> sweep = ExperimentSets.resolve("sweep-obstacle");
        ExperimentSummary hits = summary(rows(sweep, 2, (s, p, r) -> p > 100
                ? new Object[] {"stuck", 120.0, 3.0, 1} : completed(230), FALLING));
        ExperimentSummary clean = summary(rows(sweep, 2, (s, p, r) -> completed(230), FALLING));
        String md = io.rtaware.experiment.report.ResultsMarkdown.render(List.of(
                new io.rtaware.experiment.report.ResultsMarkdown.Folder("a", hits),
                new io.rtaware.experiment.report.ResultsMarkdown.Folder("b", clean)), "test");
        String lineA = md.lines().filter(l -> l.startsWith("- claim `a/slow-hits`")).findFirst().orElseThrow();
        assertTrue(lineA.contains("**Contradicted** under the same conditions (paper-room at run's default top speed, "
                + "swept: obstacle) by b/slow-hits says not_reproduced."), lineA);
        String misses = md.lines().filter(l -> l.startsWith("- claim `a/misses-fall`")).findFirst().orElseThrow();
        assertTrue(!misses.contains("Contradicted"), "the same verdict in both: " + misses);
    }

    /**
     * Two experiments on the same course, speed and swept tasks whose verdicts rest on sets of
     * different periods do not contradict each other (paper-profile's five sets against
     * sweep-all's were marked contradicted on fig7-planner-most before).
     */
    @Test
    void experimentsThatShareNoSetDoNotContradictEachOther() {
        List<PeriodSet> sweep = ExperimentSets.resolve("sweep-obstacle");
        List<PeriodSet> fiveAnd200 = sweep.stream().filter(set -> List.of(5L, 200L).contains(set.periodsMs().get("obstacle")))
                .toList();
        List<PeriodSet> tenAnd400 = sweep.stream().filter(set -> List.of(10L, 400L).contains(set.periodsMs().get("obstacle")))
                .toList();
        ExperimentSummary hits = summary(rows(fiveAnd200, 2, (s, p, r) -> p > 100
                ? new Object[] {"stuck", 120.0, 3.0, 1} : completed(230), FALLING));
        ExperimentSummary clean = summary(rows(tenAnd400, 2, (s, p, r) -> completed(230), FALLING));
        Claim a = claim(hits, "slow-hits");
        Claim b = claim(clean, "slow-hits");
        assertEquals(a.judgedOn(), b.judgedOn(), "the same course, speed and swept task");
        assertEquals(Verdict.REPRODUCED, a.verdict());
        assertEquals(Verdict.NOT_REPRODUCED, b.verdict());
        assertEquals(2, a.cells().size(), a.cells().toString());
        assertTrue(a.cells().stream().noneMatch(b.cells()::contains), a.cells() + " against " + b.cells());
        String md = io.rtaware.experiment.report.ResultsMarkdown.render(List.of(
                new io.rtaware.experiment.report.ResultsMarkdown.Folder("a", hits),
                new io.rtaware.experiment.report.ResultsMarkdown.Folder("b", clean)), "test");
        String lineA = md.lines().filter(l -> l.startsWith("- claim `a/slow-hits`")).findFirst().orElseThrow();
        assertTrue(!lineA.contains("Contradicted"), "no set in common: " + lineA);
    }

    /** The ids docs quote verdicts by, and the closing note of issue 35 names: they never change. */
    @Test
    void theIdsOfTheClaimFamiliesAndRulesAreStable() {
        assertEquals(List.of("slow-hits", "fast-locks-up", "misses-fall", "table1-set1-faster", "table1-verge",
                "table2-no-difference", "table1-set3-fastest-widest", "tables-almost-identical", "fig7-planner-most",
                "fig8-set1-most-misses", "table1-spread-twice", "fig7-set1-highest-per-task", "computation-order",
                "conclusion-timing-matters", "avoider-too-fast-hits", "sampling-rate-advice", "planner-can-slow",
                "bad-map-bad-path"), PaperClaims.familyIds());
        assertEquals(List.of("reaction-rule-bound"), PaperClaims.ruleIds());
        ExperimentSummary s = summary(rows(ExperimentSets.paper(), 2, (x, p, r) -> completed(250 + r), FALLING));
        List<String> ids = new ArrayList<>();
        s.claims().forEach(c -> ids.add(c.id()));
        s.claimsNotEvaluated().forEach(n -> ids.add(n.id()));
        assertEquals(new java.util.TreeSet<>(PaperClaims.familyIds()), new java.util.TreeSet<>(ids),
                "on the paper's course at one speed every claim has its family's id");
        assertTrue(notEvaluated(s, "bad-map-bad-path"), "no result records the map's error: " + s.claims());
    }

    @Test
    void setOneHasTheHighestMissRateOfEveryTask() {
        // all 10 ms (the paper's Set 1) against the other paper sets, all 50 and 100 ms: misses fall with the period
        Claim highest = claim(summary(rows(ExperimentSets.resolve("sweep-all"), 2, (x, p, r) -> completed(230), FALLING)),
                "fig7-set1-highest-per-task");
        assertEquals(Verdict.REPRODUCED, highest.verdict(), highest.evidence());
        assertTrue(highest.evidence().contains("waypoint: Set 1 5.00%, highest of the others all 50 ms 1.00%"),
                highest.evidence());
        // the paper's sets: Set 2 runs the avoider at 10 ms too, so its obstacle misses tie with Set 1's
        Claim tie = claim(summary(rows(ExperimentSets.paper(), 2, (x, p, r) -> completed(230), FALLING)),
                "fig7-set1-highest-per-task");
        assertEquals(Verdict.MIXED, tie.verdict(), tie.evidence());
    }

    @Test
    void computationFollowsTheOrderOfFigSevenOnlyWhenTheExecutionTimesDo() {
        List<PeriodSet> paper = ExperimentSets.paper();
        execUs = t -> Map.of("planner", 900.0, "occupancy", 500.0, "waypoint", 100.0, "obstacle", 50.0).get(t);
        assertEquals(Verdict.REPRODUCED, claim(summary(rows(paper, 2, (x, p, r) -> completed(230), FALLING)),
                "computation-order").verdict());
        execUs = t -> Map.of("planner", 900.0, "occupancy", 500.0, "waypoint", 100.0, "obstacle", 200.0).get(t);
        Claim avoiderAboveWaypoint = claim(summary(rows(paper, 2, (x, p, r) -> completed(230), FALLING)),
                "computation-order");
        assertEquals(Verdict.NOT_REPRODUCED, avoiderAboveWaypoint.verdict(), avoiderAboveWaypoint.evidence());
        assertTrue(avoiderAboveWaypoint.evidence().startsWith("Set 1: planner 900 us > occupancy 500 us > obstacle 200 us "
                + "> waypoint 100 us"), avoiderAboveWaypoint.evidence());
        execUs = t -> 50;
        assertEquals(Verdict.NOT_REPRODUCED, claim(summary(rows(paper, 2, (x, p, r) -> completed(230), FALLING)),
                "computation-order").verdict(), "equal times are no order");
    }

    /** Issue 35: the main conclusion, from the blocked test where run j of every set shares world seed j. */
    @Test
    void theConclusionIsJudgedByTheBlockedTestWhereSetsShareSeeds() {
        List<PeriodSet> paper = ExperimentSets.paper();
        // seed j makes the course 5 s longer per j; Set 1 is 3 s slower on every seed, with a little noise
        Claim differs = claim(summary(rows(paper, 6, (x, p, r) -> completed(230 + 5 * r
                + (paper.indexOf(x) == 0 ? 3 : 0) + 0.1 * ((paper.indexOf(x) * 7 + r * 3) % 5)), FALLING)),
                "conclusion-timing-matters");
        assertEquals(Verdict.REPRODUCED, differs.verdict(), differs.evidence());
        assertTrue(differs.evidence().startsWith("run time, blocked on the world seed (6 seeds complete in all 5 sets): "
                + "two-way ANOVA F(4, 20) = "), differs.evidence());
        assertTrue(differs.evidence().contains("paired differences against Set 1: Set 2 -3."), differs.evidence());
        Claim same = claim(summary(rows(paper, 6, (x, p, r) -> completed(230 + 5 * r
                + 0.1 * ((paper.indexOf(x) * 7 + r * 3) % 5)), FALLING)), "conclusion-timing-matters");
        assertEquals(Verdict.NOT_REPRODUCED, same.verdict(), "only the seed matters: " + same.evidence());
        // every set on its own seeds: no blocks, the sets are independent samples
        firstSeed = set -> 100L * set;
        Claim independent = claim(summary(rows(paper, 6, (x, p, r) -> completed(230 + 5 * r
                + (paper.indexOf(x) == 0 ? 30 : 0)), FALLING)), "conclusion-timing-matters");
        assertEquals(Verdict.REPRODUCED, independent.verdict(), independent.evidence());
        assertTrue(independent.evidence().startsWith("run time, as independent samples (the sets share no world seed): "
                + "one-way ANOVA"), independent.evidence());
        // a set none of whose runs completes (Set 1 stuck every time) is left out of the run-time test and named,
        // not a reason to test nothing
        Claim withoutSet1 = claim(summary(rows(paper, 6, (x, p, r) -> paper.indexOf(x) == 0
                ? new Object[] {"stuck", 120.0, 3.0 + 0.1 * r, 1} : completed(230 + 5 * r), FALLING)),
                "conclusion-timing-matters");
        assertTrue(withoutSet1.evidence().startsWith("run time, as independent samples (the sets share no world seed): "
                + "one-way ANOVA F = 0.00, p = 1.0000; left out, with fewer than two runs that give it: Set 1 (0)"),
                withoutSet1.evidence());
        assertEquals(List.of("100/10/100/100 ms at run's default top speed", "50/50/50/50 ms at run's default top speed",
                "100/50/100/100 ms at run's default top speed", "100/100/100/100 ms at run's default top speed",
                "10/10/10/10 ms at run's default top speed"), withoutSet1.cells(), "run time rests on Sets 2-5, the "
                + "distance on all five");
    }

    @Test
    void anAvoiderRunTooFastHitsObstaclesFromTheSweep() {
        List<PeriodSet> sweep = ExperimentSets.resolve("sweep-obstacle");
        Claim hits = claim(summary(rows(sweep, 4, (x, p, r) -> p <= 5 ? new Object[] {"stuck", 120.0, 3.0, 1}
                : completed(230), FALLING)), "avoider-too-fast-hits");
        assertEquals(Verdict.REPRODUCED, hits.verdict(), hits.evidence());
        assertTrue(hits.evidence().startsWith("runs with a collision at 5 ms or less: 4 of 4 (100 %, 95 % CI 51-100 %); "
                + "from 6 to 100 ms: 0 of 16 (0 %, 95 % CI 0-19 %), Fisher's exact p = 0.000 (swept: obstacle)"),
                hits.evidence());
        assertEquals(Verdict.NOT_REPRODUCED, claim(summary(rows(sweep, 4, (x, p, r) -> completed(230), FALLING)),
                "avoider-too-fast-hits").verdict());
        assertTrue(notEvaluated(summary(rows(ExperimentSets.paper(), 2, (x, p, r) -> completed(230), FALLING)),
                "avoider-too-fast-hits"), "no set at 5 ms or less");
    }

    @Test
    void theSamplingAdviceIsJudgedAtItsBoundOfFiftyMilliseconds() {
        List<PeriodSet> sweep = ExperimentSets.resolve("sweep-obstacle");
        Claim advised = claim(summary(rows(sweep, 10, (x, p, r) -> p > 50 && p <= 100
                ? new Object[] {"completed", 240.0, 0.3, 1} : completed(230), FALLING)), "sampling-rate-advice");
        assertEquals(Verdict.REPRODUCED, advised.verdict(), advised.evidence());
        Claim none = claim(summary(rows(sweep, 10, (x, p, r) -> completed(230), FALLING)), "sampling-rate-advice");
        assertEquals(Verdict.INCONCLUSIVE, none.verdict(), none.evidence());
        Claim against = claim(summary(rows(sweep, 10, (x, p, r) -> p <= 50
                ? new Object[] {"completed", 240.0, 0.3, 1} : completed(230), FALLING)), "sampling-rate-advice");
        assertEquals(Verdict.NOT_REPRODUCED, against.verdict(), against.evidence());
    }

    @Test
    void thePlannerCanBeSlowedUnlessTheRobotLosesItsCourse() throws Exception {
        List<PeriodSet> all = ExperimentSets.resolve("sweep-all");
        assertEquals(Verdict.REPRODUCED, claim(summary(rows(all, 4, (x, p, r) -> completed(230), FALLING)),
                "planner-can-slow").verdict());
        Claim confounded = claim(summary(rows(all, 4, (x, p, r) -> p > 100 ? new Object[] {"stuck", 120.0, 3.0, 0}
                : completed(230), FALLING)), "planner-can-slow");
        assertEquals(Verdict.INCONCLUSIVE, confounded.verdict(), "the other tasks were slowed too: " + confounded.evidence());
        Path f = dir.resolve("planner.yaml");
        java.nio.file.Files.writeString(f, "sweep:\n  tasks: [planner]\n  periods_ms: [50, 100, 200, 400]\n");
        Claim alone = claim(summary(rows(ExperimentSets.resolve(f.toString()), 4, (x, p, r) -> p > 100
                ? new Object[] {"stuck", 120.0, 3.0, 0} : completed(230), FALLING)), "planner-can-slow");
        assertEquals(Verdict.NOT_REPRODUCED, alone.verdict(), alone.evidence());
    }

    @Test
    void setThreeFastestAndWidestIsTwoPartsEachWithItsInterval() {
        List<PeriodSet> paper = ExperimentSets.paper();
        double[] wide = {200, 210, 190, 220, 180, 200};
        double[] narrow = {250, 251, 249, 250, 251, 249};
        Claim both = claim(summary(rows(paper, 6, (x, p, r) -> completed(paper.indexOf(x) == 2 ? wide[r - 1]
                : narrow[r - 1] + paper.indexOf(x)), FALLING)), "table1-set3-fastest-widest");
        assertEquals(Verdict.REPRODUCED, both.verdict(), both.evidence());
        assertTrue(both.evidence().startsWith("fastest: Set 3 200.00 s against the fastest other, Set 1 250.00 s: "
                + "difference -50.00 s (95% CI "), both.evidence());
        // Set 3 fastest by a hair and the narrowest: neither part shown
        double[] tight = {249.9, 250.0, 249.8, 249.9, 250.0, 249.8};
        Claim neither = claim(summary(rows(paper, 6, (x, p, r) -> completed(paper.indexOf(x) == 2 ? tight[r - 1]
                : narrow[r - 1] + 0.01 * paper.indexOf(x)), FALLING)), "table1-set3-fastest-widest");
        assertEquals(Verdict.NOT_REPRODUCED, neither.verdict(), neither.evidence());
        assertTrue(neither.evidence().contains(") not shown; widest: Set 3 SD 0.09 s"), neither.evidence());
    }
}
