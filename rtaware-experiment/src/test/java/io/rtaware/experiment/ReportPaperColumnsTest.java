package io.rtaware.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.experiment.report.ExperimentReport;
import io.rtaware.experiment.report.MapBackground;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The paper's figures stand beside a set only when the set is the paper's: the same periods at
 * the paper's top speed. A top-speed sweep runs the paper's periods at other speeds too, which
 * the paper never measured.
 */
class ReportPaperColumnsTest {

    @TempDir
    Path dir;

    @Test
    void aSetWithThePapersPeriodsAtAnotherTopSpeedGetsNoPaperFigures() throws Exception {
        System.setProperty("java.awt.headless", "true");
        RunConditions c = new RunConditions("paper-room", 10, 1, null);
        PeriodSet paperSet4 = ExperimentSets.paper().get(3);
        PeriodSet faster = new PeriodSet("Set 4 at 0.2 m/s", paperSet4.periodsMs(), 0.2);
        Path csv = dir.resolve(ResultsCsv.FILE_NAME);
        for (int run = 1; run <= 2; run++) {
            ResultsCsv.append(csv, new RunResult(1, run, paperSet4, c, "completed", 234.0 + run, 0.8, 20, 0, 4, 4, Map.of()));
            ResultsCsv.append(csv, new RunResult(2, run, faster, c, "completed", 120.0 + run, 0.9, 20, 0, 4, 4, Map.of()));
        }
        ExperimentSummary summary = ExperimentReport.render(dir, MapBackground.none(), true);
        assertEquals(paperSet4.periodsMs(), summary.sets().get(0).paperSet().periods().periodsMs(), "the paper's Set 4");
        assertEquals(null, summary.sets().get(1).paperSet(), "the paper ran no set at 0.2 m/s");
        List<String> lines = Files.readAllLines(dir.resolve("report.md"));
        String atPaperSpeed = tableOneRow(lines, "| " + paperSet4.name() + " |");
        String atOtherSpeed = tableOneRow(lines, "| Set 4 at 0.2 m/s |");
        assertTrue(atPaperSpeed.endsWith("| 276.97 | 5.17 |"), "Table I, the paper's Set 4: " + atPaperSpeed);
        assertTrue(atOtherSpeed.endsWith("| - | - |"), "Table I, the same periods at 0.2 m/s: " + atOtherSpeed);
    }

    /** The first line starting with {@code start} after the heading of Table I. */
    private static String tableOneRow(List<String> lines, String start) {
        int table = 0;
        while (!lines.get(table).startsWith("## Table I")) {
            table++;
        }
        for (int i = table; i < lines.size(); i++) {
            if (lines.get(i).startsWith(start)) {
                return lines.get(i);
            }
        }
        throw new AssertionError("no row " + start + " in Table I");
    }
}
