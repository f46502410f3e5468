package io.rtaware.app.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import io.rtaware.app.CliRun;
import io.rtaware.record.mcap.Compression;
import io.rtaware.record.mcap.McapWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code rtaware replay} on a short run recorded here (the built-in simulator at time scale 10):
 * every cycle of every controller task replays identically; what-if periods report as a run;
 * bad input is one line and exit status 2.
 */
class ReplayRunTest {

    @TempDir
    static Path dir;
    private static Path recording;

    @BeforeAll
    static void recordAShortRun() throws Exception {
        Path scenario = Path.of(Objects.requireNonNull(ReplayRunTest.class.getResource("/scenarios/short-leg.yaml")).toURI());
        recording = dir.resolve("run.mcap");
        CliRun run = CliRun.of("run", "--scenario", scenario.toString(), "--time-scale", "10", "--out",
                dir.resolve("run").toString(), "--quiet", "--seed", "3", "--record", recording.toString());
        assertEquals(0, run.status(), run.err());
        JsonNode report = new ObjectMapper().readTree(dir.resolve("run/report.json").toFile());
        assertEquals(0, report.path("recording").path("dropped").asLong(), "a recording without drops");
    }

    @Test
    void exactReplayOfARecordedRunIsIdenticalInEveryCycleOfEveryTask() throws Exception {
        Path out = dir.resolve("exact");
        CliRun replay = CliRun.of("replay", recording.toString(), "--out", out.toString());
        assertEquals(0, replay.status(), replay.err());
        JsonNode json = new ObjectMapper().readTree(out.resolve("replay.json").toFile());
        assertEquals("rtaware.replay/1", json.path("schema").asText());
        Set<String> tasks = new TreeSet<>();
        for (JsonNode t : json.path("tasks")) {
            tasks.add(t.path("name").asText());
            assertTrue(t.path("cycles").asLong() > 10, "cycles of " + t);
            assertEquals(t.path("cycles").asLong(), t.path("identical").asLong(), "every cycle identical: " + t);
            assertEquals(0, t.path("different").asLong());
            assertTrue(t.path("first_difference").isNull());
            assertTrue(t.path("exec_us").path("max").asDouble() >= t.path("exec_us").path("p50").asDouble());
        }
        assertEquals(new TreeSet<>(Set.of("waypoint", "obstacle", "occupancy", "planner", "mediator")), tasks);
        assertTrue(replay.out().contains("cycles/s"), replay.out());

        CliRun one = CliRun.of("replay", recording.toString(), "--task", "planner");
        assertEquals(0, one.status(), one.err());
        assertTrue(one.out().lines().anyMatch(l -> l.startsWith("planner ")), one.out());
        assertTrue(one.out().lines().noneMatch(l -> l.startsWith("obstacle ")), one.out());
    }

    /**
     * Issue 34: {@code analyze --verify} replays the recording with the recorded periods and with
     * each suggested change, prints before and after side by side, and says of every change
     * whether the replay kept or withdrew it; with the run's report, the advice is the report's.
     */
    @Test
    void analyzeVerifyChecksTheAdviceByReplayingTheRecording() {
        CliRun check = CliRun.of("analyze", "--verify", recording.toString());
        assertEquals(0, check.status(), check.err());
        String out = check.out();
        assertTrue(out.contains("replay check of " + recording + ": what-if replays with the recorded periods"), out);
        assertTrue(out.contains("before -> after (recorded periods -> the kept ones), replayed:"), out);
        for (String task : new String[] {"waypoint", "obstacle", "occupancy", "planner", "mediator"}) {
            assertTrue(out.lines().anyMatch(l -> l.startsWith("  " + task + " ") && l.contains(" -> ")),
                    "a before/after row of " + task + ":\n" + out);
        }
        assertTrue(out.lines().filter(l -> l.contains(" kept: ") || l.contains(" withdrawn: ")).count()
                == out.lines().filter(l -> l.matches("  \\S+ +\\S+ -> \\S+ +(kept|withdrawn): .*")).count(), out);
        assertTrue(out.contains("advice (one period per task from every rule"), out);

        CliRun withReport = CliRun.of("analyze", dir.resolve("run/report.json").toString(), "--verify",
                recording.toString());
        assertEquals(0, withReport.status(), withReport.err());
        assertTrue(withReport.out().startsWith("machine: "), withReport.out());
        assertTrue(withReport.out().contains("before -> after"), withReport.out());
    }

    @Test
    void whatIfReplayPrintsTheRunSummaryAdviceAndSchedulabilityOpenLoop() throws Exception {
        Path out = dir.resolve("whatif");
        CliRun replay = CliRun.of("replay", recording.toString(), "--periods", "planner=300ms", "--out", out.toString());
        assertEquals(0, replay.status(), replay.err());
        assertTrue(replay.out().contains("open loop, the robot's path is the recorded one"), replay.out());
        assertTrue(replay.out().contains("schedulability"), replay.out());
        assertTrue(replay.out().contains("advice"), replay.out());
        JsonNode report = new ObjectMapper().readTree(out.resolve("report.json").toFile());
        assertEquals("rtaware.report/1", report.path("schema").asText());
        assertTrue(report.path("replay").path("open_loop").asBoolean());
        assertEquals(300.0, report.path("replay").path("periods_ms").path("planner").asDouble());
        boolean planner = false;
        for (JsonNode t : report.path("tasks")) {
            if (t.path("name").asText().equals("planner")) {
                planner = true;
                assertEquals(300.0, t.path("period_ms").asDouble());
            }
        }
        assertTrue(planner, "planner in the report");
    }

    @Test
    void badInputIsOneLineWithStatus2() throws Exception {
        CliRun.of("replay", dir.resolve("missing.mcap").toString()).assertOneLineUserError("no such file");
        Path text = Files.writeString(dir.resolve("notes.mcap"), "not an mcap file, just text long enough for the checks");
        CliRun.of("replay", text.toString()).assertOneLineUserError("not an MCAP file");
        byte[] whole = Files.readAllBytes(recording);
        Path truncated = Files.write(dir.resolve("truncated.mcap"), Arrays.copyOf(whole, whole.length / 2));
        CliRun.of("replay", truncated.toString()).assertOneLineUserError("not finished");
        byte[] corrupt = whole.clone();
        for (int i = whole.length / 3; i < whole.length / 3 + 64; i++) {
            corrupt[i] ^= 0x5a;
        }
        Path damaged = Files.write(dir.resolve("damaged.mcap"), corrupt);
        CliRun.of("replay", damaged.toString()).assertOneLineUserError("damaged.mcap");
        for (int k = 1; k <= 6; k++) {
            byte[] flipped = whole.clone();
            int at = (int) ((long) whole.length * k / 7);
            flipped[at] ^= 0x01;
            CliRun run = CliRun.of("replay", Files.write(dir.resolve("flip" + k + ".mcap"), flipped).toString());
            assertTrue(run.status() == 0 || run.status() == 2, "status " + run.status() + ": " + run.err());
            assertTrue(!run.err().contains("\tat ") && !run.err().contains("Exception in"), run.err());
        }
        Path empty = dir.resolve("empty.mcap");
        try (McapWriter writer = new McapWriter(empty, Compression.NONE, McapWriter.DEFAULT_CHUNK_BYTES, "")) {
            writer.addMetadata("rtaware.run", Map.of("command", "bench"));
        }
        CliRun.of("replay", empty.toString()).assertOneLineUserError("no /rtaware/timing channels");
        CliRun.of("replay", recording.toString(), "--task", "steering")
                .assertOneLineUserError("unknown task 'steering'");
        CliRun.of("replay", recording.toString(), "--task", "steering").assertOneLineUserError("tasks: waypoint");
        CliRun.of("replay", recording.toString(), "--periods", "planner=fast").assertOneLineUserError("'fast'");
        CliRun.of("replay", recording.toString(), "--periods", "steering=50").assertOneLineUserError("unknown task 'steering'");
        CliRun.of("replay", recording.toString(), "--periods", "planner=0").assertOneLineUserError("must be positive");
        // Issue 24: a 10 ns planner divided by zero in the advice, then would have replayed for hours.
        CliRun.of("replay", recording.toString(), "--periods", "planner=10ns")
                .assertOneLineUserError("a what-if replay makes at most 2e+07");
        CliRun.of("replay", recording.toString(), "--periods", "planner=50ms", "--task", "planner")
                .assertOneLineUserError("exclude each other");
    }
}
