package io.rtaware.app.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import io.rtaware.app.RtawareCli;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Objects;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A real run's conditions on the real machine (wall clock, tagged {@code wall-clock}): beside a
 * CPU burner that the test starts and stops, the run is labelled busy with the burner's share
 * named. That a run alone on a quiet machine is quiet cannot be asserted on a machine others may
 * load (a test that skips unless quiet and then asserts quiet cannot fail, so there is none);
 * the rule itself is tested exactly on fixtures ({@code MachineVerdictTest},
 * {@code ConditionsMeterTest}).
 */
class RunConditionsEndToEndTest {

    @TempDir
    Path dir;

    private String run(Path out, String... extra) throws Exception {
        Path scenario = Path.of(Objects.requireNonNull(getClass().getResource("/scenarios/short-leg.yaml")).toURI());
        PrintStream saved = System.out;
        ByteArrayOutputStream stdout = new ByteArrayOutputStream();
        try {
            System.setOut(new PrintStream(stdout, true, StandardCharsets.UTF_8));
            String[] args = {"run", "--scenario", scenario.toString(), "--time-scale", "10", "--out", out.toString(),
                    "--quiet", "--seed", "7"};
            String[] all = java.util.Arrays.copyOf(args, args.length + extra.length);
            System.arraycopy(extra, 0, all, args.length, extra.length);
            assertEquals(0, RtawareCli.execute(all), "exit status; output:\n" + stdout);
        } finally {
            System.setOut(saved);
        }
        return stdout.toString(StandardCharsets.UTF_8);
    }

    @Test
    void aRunBesideACpuBurnerIsBusyAndNamesTheBurnersShare() throws Exception {
        assumeTrue(Files.isReadable(Path.of("/proc/stat")), "needs Linux's /proc/stat");
        Process burner = new ProcessBuilder("sh", "-c", "while :; do :; done").start();
        String printed;
        try {
            printed = run(dir.resolve("busy"), "--record", dir.resolve("busy.mcap").toString());
        } finally {
            burner.destroyForcibly();
            burner.waitFor(10, TimeUnit.SECONDS);
        }
        JsonNode conditions = new ObjectMapper().readTree(dir.resolve("busy/report.json").toFile()).path("conditions");
        assertEquals("busy", conditions.path("machine").asText(), conditions.toString());
        double other = conditions.path("measured").path("other_cpus").asDouble();
        // The burner alone keeps one CPU busy whenever the scheduler lets it; with the run on the
        // other core and under other load it gets less, never none.
        assertTrue(other > 0.3, "the burner's share is measured: " + other + " CPUs");
        assertTrue(conditions.path("machine_reasons").get(0).asText().startsWith("other processes used"),
                conditions.toString());
        assertTrue(printed.contains("machine: busy (other processes used"), "the summary says so:\n" + printed);
        assertTrue(Files.readString(dir.resolve("busy/report.md")).contains("machine: busy (other processes used"),
                "and report.md");
        assertTrue(conditions.path("setup").path("logical_cpus").asInt() > 0, conditions.toString());
        assertTrue(conditions.path("setup").path("jvm_version").asText().length() > 0, conditions.toString());
        McapMetadataCheck.assertConditionsRecord(dir.resolve("busy.mcap"), "busy");
    }
}
