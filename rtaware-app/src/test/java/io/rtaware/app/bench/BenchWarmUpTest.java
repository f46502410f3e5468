package io.rtaware.app.bench;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import io.rtaware.app.CliRun;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code bench --warmup}: a run before the measured one whose numbers are not counted. */
class BenchWarmUpTest {

    @TempDir
    Path dir;

    @Test
    void theWarmUpRunsFirstAndItsReleasesAreNotInTheReport() throws Exception {
        Path json = dir.resolve("bench.json");
        CliRun r = CliRun.of("bench", "--tasks", "2", "--period", "10ms", "--work", "0", "--duration", "300ms",
                "--warmup", "600ms", "--quiet", "--json", json.toString());
        assertEquals(0, r.status(), r.err());
        assertTrue(r.err().contains("rtaware bench: warm-up, 2 task(s) and one that overruns now and then, for 600ms"
                + " (not counted)"), r.err());
        JsonNode tasks = new ObjectMapper().readTree(Files.readString(json)).path("tasks");
        assertEquals(2, tasks.size(), "the warm-up's overrunning task is not in the measured report: " + tasks);
        JsonNode task = tasks.get(0);
        long releases = task.path("releases").asLong();
        // 300 ms at 10 ms: about 30 releases; with the warm-up's 60 counted it would be 90.
        assertTrue(releases >= 1 && releases <= 45, releases + " releases reported");
    }

    @Test
    void warmUpZeroRunsNone() {
        CliRun r = CliRun.of("bench", "--tasks", "1", "--period", "10ms", "--work", "0", "--duration", "100ms",
                "--warmup", "0", "--quiet");
        assertEquals(0, r.status(), r.err());
        assertFalse(r.err().contains("warm-up"), r.err());
    }

    @Test
    void aBadWarmUpIsOneLine() {
        CliRun.of("bench", "--warmup", "soon").assertOneLineUserError("--warmup");
    }
}
