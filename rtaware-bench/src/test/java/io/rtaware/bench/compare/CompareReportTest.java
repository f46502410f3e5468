package io.rtaware.bench.compare;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The JSON names of issue 8, the totals and the goal lines, from fixed numbers. */
class CompareReportTest {

    private static final long PERIOD = 10_000_000;

    private static RunResult row(String executor, double p99, long bursts, double alloc) {
        return new RunResult(executor, new RunResult.Lateness(50, p99, 2 * p99, 3 * p99), 1000, 0, bursts, 1.5, alloc);
    }

    @Test
    void jsonKeepsTheSchemaOfTheIssue() throws Exception {
        List<RunResult> runs = List.of(row("rtaware", 110, 0, 0), row("stpe", 120, 0, 24), row("park-loop", 100, 0, 0));
        CompareReport report = new CompareReport(CompareReport.SCHEMA, 8, 10, 1, 30, 2, 0, 0, "17", "G1",
                runs, Goal.check(runs), PairedRounds.check(runs));
        JsonNode json = new ObjectMapper().readTree(report.toJson());
        assertEquals("rtaware.bench-compare/1", json.get("schema").asText());
        assertEquals(8, json.get("tasks").asInt());
        assertEquals(10.0, json.get("period_ms").asDouble());
        assertEquals(1.0, json.get("work_ms").asDouble());
        assertEquals(3, json.get("runs").size());
        assertEquals("rtaware", json.get("runs").get(0).get("executor").asText());
        assertEquals("stpe", json.get("runs").get(1).get("executor").asText());
        assertEquals("park-loop", json.get("runs").get(2).get("executor").asText());
        JsonNode r = json.get("runs").get(1);
        for (String key : List.of("p50", "p99", "p999", "max")) {
            assertTrue(r.get("lateness_us").has(key), key);
        }
        assertEquals(240.0, r.get("lateness_us").get("p999").asDouble());
        for (String key : List.of("releases", "misses", "bursts", "cpu_us_per_release", "alloc_bytes_per_release")) {
            assertTrue(r.has(key), key);
        }
        assertEquals(24.0, r.get("alloc_bytes_per_release").asDouble());
    }

    @Test
    void goalsCompareRtawareWithTheFloorAndWithStpe() {
        List<Goal> goals = Goal.check(List.of(row("rtaware", 110, 0, 0), row("stpe", 100, 0, 0),
                row("park-loop", 100, 0, 0)));
        assertEquals(7, goals.size(), "issue 8's four, then issue 16's misses, p99.9 and miss share");
        assertTrue(goals.get(0).pass(), "1.10 <= 1.25");
        assertEquals("1.10 (110.0 / 100.0 us)", goals.get(0).value());
        assertFalse(goals.get(1).pass(), "110 > 100");
        assertTrue(goals.get(2).pass());
        assertTrue(goals.get(3).pass());

        List<Goal> bad = Goal.check(List.of(row("rtaware", 126, 2, 8), row("park-loop", 100, 0, 0)));
        assertEquals(6, bad.size(), "no stpe row, no stpe goal");
        assertFalse(bad.get(0).pass());
        assertFalse(bad.get(1).pass());
        assertFalse(bad.get(2).pass());
    }

    @Test
    void issue16GoalsCompareThreadedWithTheFloorAndPooledWithItsStpePeer() {
        List<RunResult> runs = List.of(
                new RunResult("rtaware", new RunResult.Lateness(50, 100, 140, 900), 1000, 9, 0, 1.5, 0),
                new RunResult("rtaware-pooled", new RunResult.Lateness(40, 90, 300, 900), 1000, 20, 0, 1.0, 0),
                new RunResult("stpe-pooled", new RunResult.Lateness(60, 95, 200, 900), 1000, 30, 0, 1.0, 0),
                new RunResult("park-loop", new RunResult.Lateness(50, 100, 100, 900), 1000, 6, 0, 1.0, 0));
        List<Goal> goals = Goal.check(runs);
        List<String> lines = goals.stream().map(g -> (g.pass() ? "PASS " : "MISS ") + g.goal() + ": " + g.value()).toList();
        assertTrue(lines.contains("PASS rtaware misses / park-loop misses <= 1.5: 1.50 (9 / 6)"), lines.toString());
        assertTrue(lines.contains("PASS rtaware p99.9 / park-loop p99.9 <= 1.5: 1.40 (140 / 100)"), lines.toString());
        assertTrue(lines.contains("PASS rtaware misses < 1.0 % of releases: 0.90 %"), lines.toString());
        assertTrue(lines.contains("MISS rtaware-pooled misses < 1.0 % of releases: 2.00 %"), lines.toString());
        assertTrue(lines.contains("PASS rtaware-pooled p99 <= stpe-pooled p99: 90.0 us vs 95.0 us"), lines.toString());
        assertTrue(lines.contains("MISS rtaware-pooled p99.9 <= stpe-pooled p99.9: 300.0 us vs 200.0 us"), lines.toString());
        assertTrue(lines.contains("PASS rtaware-pooled misses <= stpe-pooled misses: 20 vs 30"), lines.toString());
    }

    @Test
    void tablePrintsOneRowPerExecutorAndPassOrMissPerGoal() {
        List<RunResult> runs = List.of(row("rtaware", 110, 1, 0), row("park-loop", 100, 0, 0));
        String table = new CompareReport(CompareReport.SCHEMA, 2, 1, 0, 4, 2, 1, 200, "17", "ZGC", runs,
                Goal.check(runs), PairedRounds.check(runs)).table();
        assertTrue(table.contains("rtaware"));
        assertTrue(table.contains("park-loop"));
        assertTrue(table.contains("PASS goal: rtaware p99 / park-loop p99 <= 1.25: 1.10"));
        assertTrue(table.contains("MISS goal: zero bursts (rtaware): 1"));
    }

    @Test
    void totalsMergeTasksAndDivideCostsByReleases() {
        ReleaseStats a = new ReleaseStats(PERIOD);
        ReleaseStats b = new ReleaseStats(PERIOD);
        for (int k = 0; k < 100; k++) {
            a.onRun(k * PERIOD, k * PERIOD + 10_000, k * PERIOD + 20_000);
            b.onRun(k * PERIOD, k * PERIOD + (k == 99 ? 5_000_000 : 30_000), k * PERIOD + 6_000_000);
        }
        ExecutorTotals totals = new ExecutorTotals("park-loop");
        totals.add(a);
        totals.add(b);
        totals.addCost(400_000, 0);
        totals.addCost(0, 1_000);
        RunResult r = totals.result();
        assertEquals(200, r.releases());
        assertEquals(0, r.misses());
        assertEquals(0, r.bursts());
        assertEquals(2.0, r.cpuUsPerRelease());
        assertEquals(5.0, r.allocBytesPerRelease());
        assertEquals(10.0, r.latenessUs().p50(), 0.2, "2 significant digits: buckets are 1 % wide");
        assertEquals(30.0, r.latenessUs().p99(), 0.5);
        assertEquals(5000.0, r.latenessUs().max());
        assertEquals(List.of(), r.rounds(), "no round was closed");
    }

    @Test
    void totalsKeepEachRoundOnItsOwn() {
        ExecutorTotals totals = new ExecutorTotals("rtaware");
        for (int round = 0; round < 2; round++) {
            for (int task = 0; task < 2; task++) {
                ReleaseStats s = new ReleaseStats(PERIOD);
                for (int k = 0; k < 1000; k++) {
                    // Round 0: every release 2 us late, none missed. Round 1: task 1 misses 10 of its
                    // releases, and the slowest 0.1 % of the round's 2000 starts are 7 ms late.
                    boolean late = round == 1 && task == 1 && k < 10;
                    long start = k * PERIOD + (late ? 7_000_000 : 2_000);
                    s.onRun(k * PERIOD, start, late ? start + 4_000_000 : start + 1_000);
                }
                totals.add(s);
            }
            totals.endRound();
        }
        RunResult r = totals.result();
        assertEquals(List.of(new RunResult.Round(2000, 0, 2.0), new RunResult.Round(2000, 10, 7000.0)), r.rounds());
        assertEquals(4000, r.releases());
        assertEquals(10, r.misses());
    }

    @Test
    void theMissRatioGoalCarriesItsIntervalOverTheRounds() {
        List<RunResult.Round> floor = new java.util.ArrayList<>();
        List<RunResult.Round> twice = new java.util.ArrayList<>();
        for (int round = 0; round < 10; round++) {
            floor.add(new RunResult.Round(1000, 5, 100));
            twice.add(new RunResult.Round(1000, 10, 140));
        }
        List<RunResult> runs = List.of(
                new RunResult("rtaware", new RunResult.Lateness(50, 100, 140, 900), 10_000, 100, 0, 1.5, 0, twice),
                new RunResult("park-loop", new RunResult.Lateness(50, 100, 100, 900), 10_000, 50, 0, 1.0, 0, floor));
        CompareReport report = new CompareReport(CompareReport.SCHEMA, 2, 10, 0, 20, 2, 0, 0, "17", "ZGC", runs,
                Goal.check(runs), PairedRounds.check(runs));
        String table = report.table();
        assertTrue(table.contains("MISS goal: rtaware misses / park-loop misses <= 1.5: 2.00 (100 / 50;"
                + " 95 % CI 2.00-2.00 over 10 rounds)"), table);
        assertTrue(table.contains("paired: rtaware vs park-loop over 10 rounds: misses x2.00 (95 % CI 2.00-2.00),"
                + " more in 10 rounds, fewer in 0, Wilcoxon p = 0.002; p99.9 x1.40 (median round), higher in 10,"
                + " lower in 0, p = 0.002"), table);
    }

    @Test
    void executorsWithAThreadPerTaskRunUpToAThousandTasksPerCore() {
        int cores = Runtime.getRuntime().availableProcessors();
        assertTrue(CompareRun.threadPerTaskFits(1000), "issue 16's 1000-task comparison keeps every row");
        assertTrue(CompareRun.threadPerTaskFits(1000 * cores));
        assertFalse(CompareRun.threadPerTaskFits(1000 * cores + 1));
    }
}
