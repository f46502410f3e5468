package io.rtaware.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Rows that cannot be runs of one plan are refused with their line; a torn last line is reported. */
class ResultsCsvIntegrityTest {

    @TempDir
    Path dir;

    private static RunResult row(int set, int run, PeriodSet periods) {
        return new RunResult(set, run, periods, new RunConditions("paper-room", 10, 1, null), "completed", 230.0, 0.2,
                20.0, 0, 4, 4, Map.of());
    }

    @Test
    void aDuplicatedSetAndRunIsRefusedWithBothLines() throws Exception {
        Path f = dir.resolve(ResultsCsv.FILE_NAME);
        PeriodSet s1 = ExperimentSets.paper().get(0);
        ResultsCsv.append(f, row(1, 1, s1));
        ResultsCsv.append(f, row(1, 2, s1));
        ResultsCsv.append(f, row(1, 1, s1));
        ExperimentInputException e = assertThrows(ExperimentInputException.class, () -> ResultsCsv.read(f));
        assertTrue(e.getMessage().contains("line 4: set 1 run 1 is already on line 2"), e.getMessage());
    }

    @Test
    void aSetWithOtherPeriodsThanAnEarlierRowIsRefused() throws Exception {
        Path f = dir.resolve(ResultsCsv.FILE_NAME);
        ResultsCsv.append(f, row(1, 1, ExperimentSets.paper().get(0)));
        ResultsCsv.append(f, row(1, 2, ExperimentSets.paper().get(4)));
        ExperimentInputException e = assertThrows(ExperimentInputException.class, () -> ResultsCsv.read(f));
        assertTrue(e.getMessage().contains("line 3: set 1 is 'Set 5'"), e.getMessage());
    }

    @Test
    void aTornLastLineIsReportedWithItsLineNumber() throws Exception {
        Path f = dir.resolve(ResultsCsv.FILE_NAME);
        ResultsCsv.append(f, row(1, 1, ExperimentSets.paper().get(0)));
        assertTrue(ResultsCsv.tornLastLine(f).isEmpty(), "a whole file");
        Files.writeString(f, "1,Set 1,2,paper-ro", StandardOpenOption.APPEND);
        String note = ResultsCsv.tornLastLine(f).orElseThrow();
        assertTrue(note.contains("line 3 is incomplete"), note);
        assertEquals(1, ResultsCsv.read(f).size(), "the torn line is not a run");
    }

    @Test
    void theRunnerRefusesARowOfASetThePlanLacksNamingItsLine() throws Exception {
        Path f = dir.resolve(ResultsCsv.FILE_NAME);
        ResultsCsv.append(f, row(1, 1, ExperimentSets.paper().get(0)));
        ResultsCsv.append(f, row(3, 1, ExperimentSets.paper().get(2)));
        ExperimentPlan plan = new ExperimentPlan(List.of(ExperimentSets.paper().get(0)), 1,
                new RunConditions("paper-room", 10, 1, null));
        ExperimentRunner runner = new ExperimentRunner(plan, args -> List.of("false"), dir,
                new ProgressBar(new java.io.PrintStream(java.io.OutputStream.nullOutputStream()), false, System::nanoTime, 1));
        ExperimentInputException e = assertThrows(ExperimentInputException.class, runner::run);
        assertTrue(e.getMessage().contains("line 3 (set 3 run 1) has set 3 but only 1 sets are planned"), e.getMessage());
    }
}
