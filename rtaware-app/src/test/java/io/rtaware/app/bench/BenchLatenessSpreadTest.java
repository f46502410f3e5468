package io.rtaware.app.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import io.rtaware.app.CliRun;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code bench} says how the tasks' p99 lateness spreads: the median task's and the worst's. */
class BenchLatenessSpreadTest {

    @TempDir
    Path dir;

    @Test
    void theLineAndTheJsonSectionAgreeWithThePerTaskFigures() throws Exception {
        Path json = dir.resolve("bench.json");
        CliRun r = CliRun.of("bench", "--executor", "pooled", "--tasks", "3", "--period", "10ms", "--work", "0",
                "--duration", "300ms", "--warmup", "0", "--quiet", "--json", json.toString());
        assertEquals(0, r.status(), r.err());
        JsonNode doc = new ObjectMapper().readTree(Files.readString(json));
        List<Double> p99 = new ArrayList<>();
        String worst = null;
        double worstP99 = -1;
        for (JsonNode task : doc.path("tasks")) {
            double taskP99 = task.path("lateness_us").path("p99").asDouble();
            p99.add(taskP99);
            if (taskP99 > worstP99) {
                worstP99 = taskP99;
                worst = task.path("name").asText();
            }
        }
        p99.sort(null);
        JsonNode spread = doc.path(BenchCommand.LATENESS_SPREAD_SECTION);
        assertEquals(3, spread.path("tasks").asInt());
        assertEquals(p99.get(1), spread.path("median_p99_us").asDouble(), 1e-9, "the middle of three");
        assertEquals(worstP99, spread.path("worst_p99_us").asDouble(), 1e-9);
        assertEquals(worst, spread.path("worst_task").asText());
        assertEquals(doc.path("misses_total_pct").asDouble(), spread.path("misses_total_pct").asDouble(), 1e-9);
        assertTrue(r.out().contains("p99 lateness over 3 periodic tasks: the median task's "), r.out());
        assertTrue(r.out().contains(" (" + worst + "); misses "), r.out());
    }
}
