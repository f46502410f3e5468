package io.rtaware.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.experiment.report.ExperimentReport;
import io.rtaware.experiment.report.MapBackground;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Run times or distances a run did not give (NaN, empty) are left out of the statistics and figures, never passed to a chart. */
class ReportWithMissingValuesTest {

    @TempDir
    Path dir;

    @Test
    void nanRunTimesAreLeftOutAndTheReportIsWritten() throws Exception {
        System.setProperty("java.awt.headless", "true");
        RunConditions c = new RunConditions("paper-room", 10, 1, null);
        PeriodSet s1 = ExperimentSets.paper().get(0);
        PeriodSet s2 = ExperimentSets.paper().get(1);
        Path csv = dir.resolve(ResultsCsv.FILE_NAME);
        ResultsCsv.append(csv, new RunResult(1, 1, s1, c, "completed", Double.NaN, Double.NaN, 20, 0, 4, 4, Map.of()));
        ResultsCsv.append(csv, new RunResult(2, 1, s2, c, "completed", 230.0, 0.2, 20, 0, 4, 4, Map.of()));
        ResultsCsv.append(csv, new RunResult(1, 2, s1, c, "completed", 231.0, Double.POSITIVE_INFINITY, 20, 0, 4, 4, Map.of()));
        ResultsCsv.append(csv, new RunResult(3, 1, ExperimentSets.paper().get(2), c, "completed", Double.NaN, Double.NaN,
                Double.NaN, 0, 4, 4, Map.of()));
        // A hand-edited or foreign file may say NaN outright.
        String text = Files.readString(csv);
        Files.writeString(csv, text + "2,Set 2,2,paper-room,10,2,,100,10,100,100,completed,NaN,NaN,Infinity,0,4,4"
                + ",".repeat(ResultsCsv.HEADER.size() - 18) + "\n");
        ExperimentSummary summary = ExperimentReport.render(dir, MapBackground.none(), true);
        assertEquals(1, summary.sets().get(0).runTimeS().n(), "the NaN run time is not a sample");
        assertEquals(1, summary.sets().get(1).runTimeS().n(), "nor the one written as NaN");
        assertEquals(0, summary.sets().get(2).runTimeS().n(), "a set whose only run time is NaN has none");
        String json = Files.readString(dir.resolve("summary.json"));
        assertFalse(json.contains("NaN") || json.contains("Infinity"), json);
        assertTrue(Files.size(dir.resolve("runtime-box.png")) > 0);
    }

    @Test
    void aFolderWhoseRunTimesAreAllNanStillGetsItsReport() throws Exception {
        System.setProperty("java.awt.headless", "true");
        Path csv = dir.resolve(ResultsCsv.FILE_NAME);
        ResultsCsv.append(csv, new RunResult(1, 1, ExperimentSets.paper().get(0), new RunConditions("paper-room", 10, 1, null),
                "completed", 1.0, 1.0, 1.0, 0, 4, 4, Map.of()));
        String[] lines = Files.readString(csv).split("\n");
        StringBuilder sb = new StringBuilder(lines[0]).append('\n');
        for (int set = 1; set <= 2; set++) {
            for (int run = 1; run <= 2; run++) {
                PeriodSet p = ExperimentSets.paper().get(set - 1);
                sb.append(set).append(",\"").append(p.name()).append("\",").append(run).append(",paper-room,10,").append(run)
                        .append(",,").append(p.periodsArgument().replaceAll("[a-z]+=|ms", "")).append(",completed,NaN,NaN,NaN,0,4,4")
                        .append(",".repeat(ResultsCsv.HEADER.size() - 18)).append('\n');
            }
        }
        Files.writeString(csv, sb);
        Path runDir = Files.createDirectories(dir.resolve("runs/set1-run1"));
        Files.writeString(runDir.resolve("trajectory.csv"), "t_s,x_m,y_m,yaw_rad\n0.0,1.0,1.0,0\n0.1,NaN,NaN,NaN\n0.2,2.0,1.5,0\n");
        Path run2 = Files.createDirectories(dir.resolve("runs/set2-run1"));
        Files.writeString(run2.resolve("trajectory.csv"), "t_s,x_m,y_m,yaw_rad\n0.0,NaN,NaN,NaN\n0.1,Infinity,1,0\n");
        ExperimentSummary summary = ExperimentReport.render(dir, MapBackground.none(), true);
        assertEquals(0, summary.sets().get(0).runTimeS().n());
        assertTrue(Files.size(dir.resolve("runtime-box.png")) > 0);
        assertTrue(Files.size(dir.resolve("report.md")) > 0);
    }
}
