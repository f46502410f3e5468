package io.rtaware.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;

class ExperimentPlanTest {

    private static final RunConditions CONDITIONS = new RunConditions("paper-room", 10, 40, null);

    @Test
    void aSetsTopSpeedIsPassedToRunAsTopSpeed() {
        PeriodSet fast = PeriodSet.of("fast", 100, 20, 100, 100).withTopSpeed(0.35);
        ExperimentPlan plan = new ExperimentPlan(List.of(fast, PeriodSet.of("default", 100, 20, 100, 100)), 2, CONDITIONS);
        List<PlannedRun> order = plan.order();
        assertEquals(List.of("--scenario", "paper-room", "--periods", "waypoint=100ms,obstacle=20ms,occupancy=100ms,planner=100ms",
                "--time-scale", "10", "--seed", "41", "--robot-seed", "4", "--top-speed", "0.35", "--out", "o", "--quiet"),
                plan.runArguments(order.get(2), Path.of("o")));
        assertFalse(plan.runArguments(order.get(1), Path.of("o")).contains("--top-speed"));
    }

    @Test
    void blockedOneRobotDrivesEveryRunUnlessTheRunsAreSpreadOverSeveralRobots() {
        PeriodSet set = PeriodSet.of("default", 100, 20, 100, 100);
        ExperimentPlan one = new ExperimentPlan(List.of(set), 5, new RunConditions("paper-room", 10, 40, null, 7, 1, ExperimentDesign.BLOCKED));
        ExperimentPlan three = new ExperimentPlan(List.of(set), 5, new RunConditions("paper-room", 10, 40, null, 7, 3, ExperimentDesign.BLOCKED));
        List<String> seedsOfOne = new ArrayList<>();
        List<String> seedsOfThree = new ArrayList<>();
        List<String> runSeeds = new ArrayList<>();
        for (PlannedRun p : one.order()) {
            List<String> args = one.runArguments(p, Path.of("o"));
            seedsOfOne.add(args.get(args.indexOf("--robot-seed") + 1));
            runSeeds.add(args.get(args.indexOf("--seed") + 1));
        }
        for (PlannedRun p : three.order()) {
            List<String> args = three.runArguments(p, Path.of("o"));
            seedsOfThree.add(args.get(args.indexOf("--robot-seed") + 1));
        }
        assertEquals(List.of("7", "7", "7", "7", "7"), seedsOfOne, "one robot: the same robot seed in every run");
        assertEquals(List.of("40", "41", "42", "43", "44"), runSeeds, "each run its own noise seed");
        assertEquals(List.of("7", "8", "9", "7", "8"), seedsOfThree, "three robots in turn");
    }

    @Test
    void blockedRunJOfEverySetSharesWorldSeedAndRobot() {
        ExperimentPlan plan = new ExperimentPlan(ExperimentSets.paper(), 3,
                new RunConditions("paper-room", 10, 40, null, 1, 1000, ExperimentDesign.BLOCKED));
        for (PlannedRun p : plan.order()) {
            List<String> args = plan.runArguments(p, Path.of("o"));
            assertEquals(Long.toString(40 + p.run() - 1), args.get(args.indexOf("--seed") + 1), p.folderName());
            assertEquals(Long.toString(p.run()), args.get(args.indexOf("--robot-seed") + 1), p.folderName());
        }
    }

    @Test
    void independentRunsEachHaveTheirOwnWorldSeedAndDrawTheirRobotFromThePopulation() {
        RunConditions c = new RunConditions("paper-room", 10, 40, null, 1, 1000, ExperimentDesign.INDEPENDENT);
        ExperimentPlan plan = new ExperimentPlan(ExperimentSets.paper(), 10, c);
        Set<String> worldSeeds = new HashSet<>();
        Set<String> robotSeeds = new HashSet<>();
        for (PlannedRun p : plan.order()) {
            List<String> args = plan.runArguments(p, Path.of("o"));
            String seed = args.get(args.indexOf("--seed") + 1);
            long robot = Long.parseLong(args.get(args.indexOf("--robot-seed") + 1));
            assertTrue(worldSeeds.add(seed), "world seed " + seed + " of " + p.folderName() + " is used once");
            assertTrue(robot >= 1 && robot <= 1000, "robot " + robot + " is in the population");
            robotSeeds.add(Long.toString(robot));
            assertEquals(40 + (p.set() - 1) * ExperimentDesign.SET_SEED_STRIDE + p.run() - 1, Long.parseLong(seed));
        }
        assertEquals(50, worldSeeds.size());
        // 50 draws from 1000 robots: the chance that two share a robot is about 71 %, that more than
        // three do is small; the draws are fixed by the seed, so this is exact for seed 40.
        assertTrue(robotSeeds.size() >= 45, "50 runs drew " + robotSeeds.size() + " distinct robots");
        ExperimentPlan again = new ExperimentPlan(ExperimentSets.paper(), 10, c);
        assertEquals(plan.runArguments(plan.order().get(7), Path.of("o")),
                again.runArguments(again.order().get(7), Path.of("o")), "deterministic");
    }

    @Test
    void independentDrawsAreSpreadOverThePopulation() {
        RunConditions c = new RunConditions("paper-room", 10, 1, null, 1, 10, ExperimentDesign.INDEPENDENT);
        int[] counts = new int[10];
        for (int set = 1; set <= 100; set++) {
            for (int run = 1; run <= 100; run++) {
                counts[(int) (c.robotSeedOf(set, run) - 1)]++;
            }
        }
        for (int i = 0; i < 10; i++) {
            // 10 000 draws, 1 000 expected per robot, SD 30: 850..1150 is five SDs either side.
            assertTrue(counts[i] > 850 && counts[i] < 1150, "robot " + (i + 1) + " drawn " + counts[i] + " times");
        }
    }

    @Test
    void theOptionsGiveThePopulationOrTheOneNamedRobot() {
        RunConditions defaults = RunConditions.ofPopulation("paper-room", 10, 1, null, null, null, ExperimentDesign.INDEPENDENT);
        assertEquals(List.of(RunConditions.POPULATION_FIRST_ROBOT_SEED, (long) RunConditions.POPULATION_ROBOTS),
                List.of(defaults.robotSeed(), (long) defaults.robots()));
        RunConditions one = RunConditions.ofPopulation("paper-room", 10, 1, null, 4L, null, ExperimentDesign.INDEPENDENT);
        assertEquals(List.of(4L, 1L), List.of(one.robotSeed(), (long) one.robots()));
        for (int run = 1; run <= 5; run++) {
            assertEquals(4, one.robotSeedOf(3, run), "--robot-seed alone: every run drives that robot");
        }
        RunConditions sized = RunConditions.ofPopulation("paper-room", 10, 1, null, null, 20, ExperimentDesign.BLOCKED);
        assertEquals(List.of(1L, 20L), List.of(sized.robotSeed(), (long) sized.robots()));
        ExperimentInputException e = assertThrows(ExperimentInputException.class, () -> RunConditions.ofPopulation(
                "paper-room", 10, 1, null, null, 0, ExperimentDesign.BLOCKED));
        assertEquals("--robots must be at least 1, got 0", e.getMessage());
        assertEquals("the design must be one of [independent, blocked], got 'paired'",
                assertThrows(ExperimentInputException.class, () -> ExperimentDesign.parse("paired")).getMessage());
    }

    @Test
    void aCpuLimitIsPassedToEveryRunAndKeptInPlanJsonAndResultsCsv(@org.junit.jupiter.api.io.TempDir Path dir)
            throws Exception {
        RunConditions c = new RunConditions("paper-room", 10, 1, null, 1, 1000, ExperimentDesign.INDEPENDENT).withCpuLimit(0.5);
        ExperimentPlan plan = new ExperimentPlan(ExperimentSets.paper(), 2, c);
        List<String> args = plan.runArguments(plan.order().get(3), Path.of("o"));
        assertEquals("0.5", args.get(args.indexOf("--cpu-limit") + 1));
        PlanFile.write(dir, plan);
        assertEquals(plan, PlanFile.read(dir).orElseThrow());
        RunResult r = new RunResult(1, 2, plan.sets().get(0), c, "completed", 230, 0.5, 20, 0, 4, 4, Map.of());
        Path csv = dir.resolve(ResultsCsv.FILE_NAME);
        ResultsCsv.append(csv, r);
        assertEquals(c, ResultsCsv.read(csv).get(0).conditions());
        assertEquals(List.of(), new ExperimentPlan(ExperimentSets.paper(), 1, c.withCpuLimit(null))
                .runArguments(plan.order().get(0), Path.of("o")).stream().filter("--cpu-limit"::equals).toList());
        assertEquals("--cpu-limit must be a number of CPUs from 0.01 to 1024, got 0.0",
                assertThrows(IllegalArgumentException.class, () -> c.withCpuLimit(0.0)).getMessage());
    }

    @Test
    void theWorldSeedOfARunGivesBackThePlansSeed() {
        for (ExperimentDesign d : ExperimentDesign.values()) {
            for (int set = 1; set <= 9; set++) {
                for (int run = 1; run <= 12; run++) {
                    assertEquals(-3, d.planSeed(d.worldSeed(-3, set, run), set, run), d + " set " + set + " run " + run);
                }
            }
        }
    }

    @Test
    void shardsPartitionTheWholePlanWithTheSameSeeds() {
        List<PeriodSet> sets = ExperimentSets.resolve("sweep-obstacle");
        ExperimentPlan whole = new ExperimentPlan(sets, 10, CONDITIONS);
        for (int n = 1; n <= 12; n++) {
            List<String> seen = new ArrayList<>();
            for (int k = 1; k <= n; k++) {
                ExperimentPlan shard = new ExperimentPlan(sets, 10, CONDITIONS, new Shard(k, n));
                List<PlannedRun> mine = shard.order();
                if (10 % n == 0) {
                    assertEquals(80 / n, mine.size(), "shard " + k + "/" + n + ": equal shares when N divides the runs");
                }
                for (PlannedRun p : mine) {
                    seen.add(p.folderName() + " " + shard.runArguments(p, Path.of(p.folderName())));
                }
                assertEquals(whole.fullOrder().stream().filter(mine::contains).toList(), mine, "whole plan's order");
            }
            List<String> expected = whole.fullOrder().stream()
                    .map(p -> p.folderName() + " " + whole.runArguments(p, Path.of(p.folderName()))).toList();
            assertEquals(new HashSet<>(expected), new HashSet<>(seen), "every run with its arguments and seed, n = " + n);
            assertEquals(expected.size(), seen.size(), "no run twice, n = " + n);
        }
    }

    @Test
    void eachSetsRunsAreSpreadEvenlyOverTheShards() {
        ExperimentPlan a = new ExperimentPlan(ExperimentSets.resolve("sweep-all"), 10, CONDITIONS, new Shard(1, 2));
        for (int set = 1; set <= 8; set++) {
            int s = set;
            assertEquals(5, a.order().stream().filter(p -> p.set() == s).count(), "set " + set);
        }
        Set<Integer> sets = new HashSet<>();
        new ExperimentPlan(ExperimentSets.paper(), 3, CONDITIONS, new Shard(3, 3)).order().forEach(p -> sets.add(p.set()));
        assertEquals(Set.of(1, 2, 3, 4, 5), sets);
    }

    @Test
    void shardTextIsKOverN() {
        assertEquals(new Shard(2, 4), Shard.parse("2/4"));
        for (String bad : List.of("0/4", "5/4", "2", "a/b", "1/0", "1/2/3", "")) {
            ExperimentInputException e = assertThrows(ExperimentInputException.class, () -> Shard.parse(bad));
            assertTrue(e.getMessage().contains("'" + bad + "'"), e.getMessage());
        }
    }
}
