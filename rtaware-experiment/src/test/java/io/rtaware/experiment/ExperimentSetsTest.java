package io.rtaware.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ExperimentSetsTest {

    @TempDir
    Path dir;

    @Test
    void paperIsTableOne() {
        List<PeriodSet> sets = ExperimentSets.resolve("paper");
        assertEquals(5, sets.size());
        assertEquals("10/10/10/10", sets.get(0).shortLabel());
        assertEquals("100/10/100/100", sets.get(1).shortLabel());
        assertEquals("50/50/50/50", sets.get(2).shortLabel());
        assertEquals("100/50/100/100", sets.get(3).shortLabel());
        assertEquals("100/100/100/100", sets.get(4).shortLabel());
        assertEquals("waypoint=100ms,obstacle=50ms,occupancy=100ms,planner=100ms", sets.get(3).periodsArgument());
    }

    @Test
    void readsYamlInTaskOrderWithDefaultNames() throws Exception {
        Path f = write("sets:\n  - periods_ms: {planner: 40, occupancy: 30, obstacle: 20, waypoint: 10}\n"
                + "  - name: fast\n    periods_ms: {waypoint: 5, obstacle: 5, occupancy: 5, planner: 5}\n");
        List<PeriodSet> sets = ExperimentSets.resolve(f.toString());
        assertEquals("Set 1", sets.get(0).name());
        assertEquals("10/20/30/40", sets.get(0).shortLabel());
        assertEquals("fast", sets.get(1).name());
    }

    @Test
    void builtInSweepsVaryTheObstacleOrAllFourFrom5To800Ms() {
        List<PeriodSet> obstacle = ExperimentSets.resolve("sweep-obstacle");
        assertEquals(List.of("100/5/100/100", "100/10/100/100", "100/20/100/100", "100/50/100/100", "100/100/100/100",
                "100/200/100/100", "100/400/100/100", "100/800/100/100"), obstacle.stream().map(PeriodSet::shortLabel).toList());
        assertEquals("obstacle 5 ms", obstacle.get(0).name());
        assertNull(obstacle.get(0).topSpeedMps());
        List<PeriodSet> all = ExperimentSets.resolve("sweep-all");
        assertEquals(List.of("5/5/5/5", "10/10/10/10", "20/20/20/20", "50/50/50/50", "100/100/100/100", "200/200/200/200",
                "400/400/400/400", "800/800/800/800"), all.stream().map(PeriodSet::shortLabel).toList());
        assertEquals("all 800 ms", all.get(7).name());
    }

    @Test
    void yamlSweepCombinesSpeedsAndPeriodsSpeedsOutermost() throws Exception {
        Path f = write("sweep:\n  tasks: [planner, obstacle]\n  periods_ms: [20, 400]\n"
                + "  base_periods_ms: {waypoint: 50}\n  top_speed_mps: [0.1, 0.3]\n");
        List<PeriodSet> sets = ExperimentSets.resolve(f.toString());
        assertEquals(List.of("obstacle+planner 20 ms at 0.1 m/s", "obstacle+planner 400 ms at 0.1 m/s",
                "obstacle+planner 20 ms at 0.3 m/s", "obstacle+planner 400 ms at 0.3 m/s"),
                sets.stream().map(PeriodSet::name).toList());
        assertEquals("50/20/100/20", sets.get(0).shortLabel());
        assertEquals("50/400/100/400 at 0.3 m/s", sets.get(3).label());
        assertEquals(0.3, sets.get(3).topSpeedMps());
    }

    @Test
    void yamlSpeedSweepAndOneSpeedForAPeriodSweep() throws Exception {
        List<PeriodSet> speeds = ExperimentSets.resolve(write("sweep:\n  top_speed_mps: [0.1, 0.25, 0.4]\n").toString());
        assertEquals(List.of("0.1 m/s", "0.25 m/s", "0.4 m/s"), speeds.stream().map(PeriodSet::name).toList());
        assertEquals("100/100/100/100", speeds.get(2).shortLabel());
        List<PeriodSet> one = ExperimentSets.resolve(write("sweep:\n  periods_ms: [5, 50]\n  top_speed_mps: 0.4\n").toString());
        assertEquals(List.of("all 5 ms", "all 50 ms"), one.stream().map(PeriodSet::name).toList());
        assertEquals(0.4, one.get(1).topSpeedMps());
    }

    @Test
    void aSetMayGiveItsTopSpeed() throws Exception {
        List<PeriodSet> sets = ExperimentSets.resolve(write("sets:\n  - periods_ms: {waypoint: 1, obstacle: 2, occupancy: 3, planner: 4}\n"
                + "    top_speed_mps: 0.35\n  - periods_ms: {waypoint: 1, obstacle: 2, occupancy: 3, planner: 4}\n").toString());
        assertEquals(0.35, sets.get(0).topSpeedMps());
        assertNull(sets.get(1).topSpeedMps());
        assertFalse(sets.get(0).sameRunsAs(sets.get(1)));
    }

    @Test
    void badSweepsGiveOneLineNamingFileFieldAndValue() throws Exception {
        assertError("sweep:\n  tasks: [obstacle]\n", "sweeps nothing");
        assertError("sweep:\n  periods_ms: [10]\n  top_speed_mps: 0\n", "sweep.top_speed_mps must be a number of m/s above 0");
        assertError("sweep:\n  periods_ms: [10]\n  top_speed_mps: [0.1, fast]\n", "sweep.top_speed_mps[1] must be a number");
        assertError("sweep:\n  periods_ms: [10, 0]\n", "sweep.periods_ms[1] must be a whole number of ms from 1 to 60000, got '0'");
        assertError("sweep:\n  periods_ms: [10, 10]\n", "sweep.periods_ms[1]: 10 ms is listed twice");
        assertError("sweep:\n  periods_ms: 10\n", "sweep.periods_ms must be a non-empty list");
        assertError("sweep:\n  tasks: [mapper]\n  periods_ms: [10]\n", "sweep.tasks[0]: unknown task 'mapper'");
        assertError("sweep:\n  tasks: obstacle\n  periods_ms: [10]\n", "sweep.tasks must be a non-empty list");
        assertError("sweep:\n  periods_ms: [10]\n  base_periods_ms: {planner: 9ms}\n", "sweep.base_periods_ms.planner must be");
        assertError("sweep:\n  periods_ms: [10]\n  speed: 1\n", "sweep: unknown field 'speed'");
        assertError("sweep: [1]\n", "sweep must be a mapping");
        assertError("sweep:\n  periods_ms: [10]\nsets: []\n", "either 'sets' or 'sweep'");
        assertError("sets:\n  - periods_ms: {waypoint: 1, obstacle: 1, occupancy: 1, planner: 1}\n    top_speed_mps: 9\n",
                "sets[0].top_speed_mps must be a number of m/s above 0 and at most 5.0, got '9'");
    }

    @Test
    void badFilesGiveOneLineNamingFileFieldAndValue() throws Exception {
        assertError("sets: []\n", "'sets' must be a non-empty list");
        assertError("set: []\n", "unknown field 'set'");
        assertError("sets:\n  - periods_ms: {waypoint: 10, obstacle: 10, occupancy: 10}\n", "no period for task 'planner'");
        assertError("sets:\n  - periods_ms: {waypoint: 10, obstacle: 10, occupancy: 10, planner: -5}\n",
                "sets[0].periods_ms.planner must be a whole number of ms from 1 to 60000, got '-5'");
        assertError("sets:\n  - periods_ms: {waypoint: 10ms, obstacle: 10, occupancy: 10, planner: 5}\n",
                "sets[0].periods_ms.waypoint must be a whole number");
        assertError("sets:\n  - periods_ms: {waypoint: 1, obstacle: 1, occupancy: 1, planner: 1, mapper: 1}\n",
                "unknown task 'mapper'");
        assertError("sets:\n  - {name: a, periods_ms: {waypoint: 1, obstacle: 1, occupancy: 1, planner: 1}}\n"
                + "  - {name: a, periods_ms: {waypoint: 1, obstacle: 1, occupancy: 1, planner: 1}}\n", "sets[1].name 'a'");
        assertError("sets: [\n", "is not valid YAML");
        ExperimentInputException missing = assertThrows(ExperimentInputException.class,
                () -> ExperimentSets.resolve(dir.resolve("nope.yaml").toString()));
        assertTrue(missing.getMessage().contains("nope.yaml does not exist"), missing.getMessage());
    }

    private void assertError(String yaml, String expected) throws Exception {
        Path f = write(yaml);
        ExperimentInputException e = assertThrows(ExperimentInputException.class, () -> ExperimentSets.load(f));
        assertTrue(e.getMessage().startsWith("sets file " + f), e.getMessage());
        assertTrue(e.getMessage().contains(expected), e.getMessage());
        assertEquals(1, e.getMessage().lines().count(), e.getMessage());
    }

    private Path write(String yaml) throws Exception {
        Path f = Files.createTempFile(dir, "sets", ".yaml");
        Files.writeString(f, yaml);
        return f;
    }
}
