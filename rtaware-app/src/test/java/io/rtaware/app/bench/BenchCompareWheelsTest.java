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

/** {@code bench --compare --executor netty-wheel,agrona-wheel}: the timer wheels' rows, by their labels. */
class BenchCompareWheelsTest {

    @TempDir
    Path dir;

    @Test
    void theWheelRowsRunByTheirLabelsWithTheKeysOfEveryRow() throws Exception {
        Path json = dir.resolve("compare.json");
        CliRun r = CliRun.of("bench", "--compare", "--executor", "agrona-wheel,netty-wheel,stpe-pooled", "--tasks", "3",
                "--period", "5ms", "--work", "0", "--segment", "400ms", "--duration", "200ms", "--json",
                json.toString());
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().lines().anyMatch(l -> l.startsWith("netty-wheel ")), r.out());
        assertTrue(r.out().lines().anyMatch(l -> l.startsWith("agrona-wheel ")), r.out());

        JsonNode runs = new ObjectMapper().readTree(Files.readString(json)).path("runs");
        List<String> executors = new ArrayList<>();
        runs.forEach(run -> executors.add(run.path("executor").asText()));
        assertEquals(List.of("stpe-pooled", "netty-wheel", "agrona-wheel"), executors, "in the table's order");
        List<String> keys = new ArrayList<>();
        runs.get(0).fieldNames().forEachRemaining(keys::add);
        for (JsonNode run : runs) {
            List<String> own = new ArrayList<>();
            run.fieldNames().forEachRemaining(own::add);
            assertEquals(keys, own, run.path("executor").asText() + " has the keys of stpe-pooled");
            assertTrue(run.path("releases").asLong() > 0, run.toString());
        }
    }

    @Test
    void anUnknownRowIsOneLineNamingIt() {
        CliRun.of("bench", "--compare", "--executor", "netty-wheel,quartz")
                .assertOneLineUserError("--executor: no comparison row 'quartz'; rows: rtaware, rtaware-pooled");
        CliRun.of("bench", "--executor", "netty-wheel")
                .assertOneLineUserError("--executor must be threaded or pooled, got netty-wheel");
    }
}
