package io.rtaware.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
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
        assertEquals("waypoint=100,obstacle=50,occupancy=100,planner=100", sets.get(3).periodsArgument());
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
