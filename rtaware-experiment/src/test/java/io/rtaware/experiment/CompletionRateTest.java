package io.rtaware.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import io.rtaware.experiment.report.ExperimentReport;
import io.rtaware.experiment.report.MapBackground;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Each set's completion rate is in summary.json with its Wilson 95 % interval, and in the report. */
class CompletionRateTest {

    @TempDir
    Path dir;

    @Test
    void everySetHasItsCompletionRateWithAWilsonInterval() throws Exception {
        System.setProperty("java.awt.headless", "true");
        RunConditions c = new RunConditions("paper-room", 10, 1, null, 1, 1000, ExperimentDesign.INDEPENDENT);
        PeriodSet s1 = ExperimentSets.paper().get(0);
        PeriodSet s2 = ExperimentSets.paper().get(1);
        Path csv = dir.resolve(ResultsCsv.FILE_NAME);
        String[] set1 = {"completed", "stuck", "completed", "timeout", "completed"};
        for (int run = 1; run <= set1.length; run++) {
            ResultsCsv.append(csv, new RunResult(1, run, s1, c, set1[run - 1], 230.0 + run, 0.5, 20, 0, 4, 4, Map.of()));
        }
        ResultsCsv.append(csv, new RunResult(2, 1, s2, c, "stuck", 100, 3, 10, 0, 2, 4, Map.of()));
        ResultsCsv.append(csv, RunResult.error(2, 2, s2, c));
        ExperimentReport.render(dir, MapBackground.none(), true);

        JsonNode sets = new ObjectMapper().readTree(dir.resolve("summary.json").toFile()).get("sets");
        assertEquals(0.6, sets.get(0).get("completion_rate").asDouble());
        // Wilson score interval, z = 1.959964: 3 of 5 -> 0.2307..0.8824; 0 of 2 -> 0..0.6576.
        assertEquals(0.2307242812760128, sets.get(0).get("completion_rate_ci95").get(0).asDouble(), 1e-12);
        assertEquals(0.882379225767352, sets.get(0).get("completion_rate_ci95").get(1).asDouble(), 1e-12);
        assertEquals(0.0, sets.get(1).get("completion_rate").asDouble());
        assertEquals(0.0, sets.get(1).get("completion_rate_ci95").get(0).asDouble());
        assertEquals(0.6576197724933469, sets.get(1).get("completion_rate_ci95").get(1).asDouble(), 1e-12);

        String md = Files.readString(dir.resolve(ExperimentReport.MARKDOWN_FILE));
        assertTrue(md.contains("## Completion per set"), md);
        assertTrue(md.contains("| Set 1 | 3 of 5 (60 %, 95 % CI 23-88 %) |"), md);
        assertTrue(md.contains("| Set 2 | 0 of 2 (0 %, 95 % CI 0-66 %) |"), md);
    }
}
