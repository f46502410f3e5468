package io.rtaware.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ResultsCsvTest {

    @TempDir
    Path dir;

    private static RunResult sample(int run, String setName) {
        return new RunResult(2, run, PeriodSet.of(setName, 100, 10, 100, 100), new RunConditions("my, \"room\".yaml", 12.5, 40, 0.05),
                "timeout", 360.0, 1.0 / 3, 22.75, 1, 3, 4,
                Map.of("waypoint", new TaskResult(3600, 7, 7 * 100.0 / 3600, 2, 123.456),
                        "planner", new TaskResult(3600, 0, 0, 0, 9)));
    }

    @Test
    void roundTripsExactlyWithQuotingAndMissingTasks() throws Exception {
        Path f = dir.resolve("results.csv");
        RunResult a = sample(1, "Set, two");
        RunResult b = RunResult.error(2, 2, PeriodSet.of("Set, two", 100, 10, 100, 100), a.conditions());
        ResultsCsv.append(f, a);
        ResultsCsv.append(f, b);
        List<String> lines = Files.readAllLines(f);
        assertEquals(String.join(",", ResultsCsv.HEADER), lines.get(0));
        assertEquals(3, lines.size());
        assertEquals(List.of(a, b).toString(), ResultsCsv.read(f).toString());
        assertEquals(41, Long.parseLong(ResultsCsv.split(lines.get(2)).get(5)), "seed of run 2 is seed + 1");
    }

    @Test
    void anIndependentRunKeepsItsOwnWorldSeedAndRobotSeedAndReadsBackTheSameConditions() throws Exception {
        Path f = dir.resolve("results.csv");
        RunConditions c = new RunConditions("paper-room", 10, 40, null, 1, 1000, ExperimentDesign.INDEPENDENT);
        RunResult r = new RunResult(3, 7, PeriodSet.of("S", 100, 50, 100, 100), c, "completed", 233.5, 0.28, 25.0, 0, 4, 4,
                Map.of());
        ResultsCsv.append(f, r);
        List<String> fields = ResultsCsv.split(Files.readAllLines(f).get(1));
        assertEquals(Long.toString(40 + 2 * ExperimentDesign.SET_SEED_STRIDE + 6), fields.get(ResultsCsv.HEADER.indexOf("seed")));
        assertEquals(Long.toString(c.robotSeedOf(3, 7)), fields.get(ResultsCsv.HEADER.indexOf("robot_seed")));
        assertEquals("independent", fields.get(ResultsCsv.HEADER.indexOf("design")));
        RunResult read = ResultsCsv.read(f).get(0);
        assertEquals(c, read.conditions());
        assertEquals(r.worldSeed(), read.worldSeed());
        assertEquals(r.robotSeed(), read.robotSeed());
    }

    @Test
    void anExperimentJsonFromBeforeTheDesignReadsAsBlocked() throws Exception {
        Files.writeString(dir.resolve(ExperimentProfile.FILE_NAME), "{\"scenario\":\"paper-room\",\"time_scale\":10.0,"
                + "\"seed\":1,\"grid_resolution_m\":null,\"runs_per_set\":12,\"machine\":\"m\"}\n");
        ExperimentProfile p = ExperimentProfile.read(dir).orElseThrow();
        assertEquals("blocked", p.design());
        assertEquals(ExperimentDesign.BLOCKED, p.experimentDesign());
        assertEquals(null, p.cpuLimitCpus());
    }

    @Test
    void aPartialLastLineIsIgnoredOnReadAndDroppedOnAppend() throws Exception {
        Path f = dir.resolve("results.csv");
        ResultsCsv.append(f, sample(1, "S"));
        Files.writeString(f, "2,S,2,room", java.nio.file.StandardOpenOption.APPEND);
        assertEquals(1, ResultsCsv.read(f).size());
        ResultsCsv.append(f, sample(3, "S"));
        List<RunResult> rows = ResultsCsv.read(f);
        assertEquals(List.of(1, 3), rows.stream().map(RunResult::run).toList());
    }

    @Test
    void newColumnsRoundTrip() throws Exception {
        Path f = dir.resolve("results.csv");
        RunResult r = new RunResult(1, 1, PeriodSet.of("fast", 100, 5, 100, 100).withTopSpeed(0.3),
                new RunConditions("paper-room", 10, 1, null), "stuck", 80.5, 2.0, 7.25, 3, 1, 4,
                Map.of("obstacle", new TaskResult(16000, 900, 5.625, 10, 4000, 870L)),
                Map.of("obstacle", 12L, "waypoint", 700L, "stop", 3L));
        ResultsCsv.append(f, r);
        assertEquals(r, ResultsCsv.read(f).get(0));
    }

    @Test
    void aFileFromBeforeTheAppendedColumnsLoadsAndTakesNewRows() throws Exception {
        Path f = dir.resolve("results.csv");
        RunResult old = new RunResult(1, 1, PeriodSet.of("S", 100, 10, 100, 100), new RunConditions("paper-room", 10, 1, null),
                "completed", 233.5, 0.28, 25.0, 0, 4, 4, Map.of("planner", new TaskResult(2300, 20, 20 * 100.0 / 2300, 1, 5000)));
        String row = ResultsCsv.format(old);
        List<String> fields = ResultsCsv.split(row);
        int columns = ResultsCsv.FIRST_VERSION_COLUMNS;
        Files.writeString(f, String.join(",", ResultsCsv.HEADER.subList(0, columns)) + "\n"
                + String.join(",", fields.subList(0, columns)) + "\n");
        RunResult read = ResultsCsv.read(f).get(0);
        assertEquals(old.toString(), read.toString());
        assertEquals(null, read.tasks().get("planner").skipped());
        assertEquals(Map.of(), read.mediatorCycles());
        RunResult next = new RunResult(1, 2, old.periods(), old.conditions(), "stuck", 100, 1, 9, 2, 1, 4, Map.of(),
                Map.of("stop", 4L));
        ResultsCsv.append(f, next);
        assertEquals(String.join(",", ResultsCsv.HEADER), Files.readAllLines(f).get(0));
        assertEquals(List.of(old, next).toString(), ResultsCsv.read(f).toString());
    }

    @Test
    void aForeignFileIsAUserError() throws Exception {
        Path f = dir.resolve("results.csv");
        Files.writeString(f, "a,b,c\n1,2,3\n");
        assertThrows(ExperimentInputException.class, () -> ResultsCsv.read(f));
    }
}
