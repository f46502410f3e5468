package io.rtaware.app.foxglove;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import io.rtaware.app.RtawareCli;
import io.rtaware.app.ros2.Ros2PythonPeer;
import io.rtaware.app.ros2.Ros2RunEndToEndTest;
import io.rtaware.app.ros2.Ros2Wiring;
import io.rtaware.core.testing.NpmPeers;
import io.rtaware.core.testing.PythonPeers;
import io.rtaware.core.testing.Requires;
import io.rtaware.core.testing.Waits;
import io.rtaware.zenoh.NativeZenohLayer;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * End to end with Foxglove's own client: {@code rtaware run}, {@code bench} and {@code sim} with
 * {@code --foxglove 0}, watched by src/test/node/check_foxglove_live.mjs
 * ({@code @foxglove/ws-protocol}'s FoxgloveClient over {@code ws}, decoding with
 * {@code @foxglove/rosmsg2-serialization}) subscribed to every channel, /scan and the timing
 * channels among them. The client decodes every message and checks their fields; for run and
 * bench it stays until the command ends and the server closes the connection, and the messages
 * it counted are exactly those report.json says were sent, none dropped. Needs node and the
 * packages under {@code RTAWARE_NPM_PEERS} (.ci/run installs them); skipped without them, except
 * under {@code CI=true}.
 */
@Requires(NpmPeers.class)
class FoxgloveLiveEndToEndTest {

    private static final Pattern URL = Pattern.compile("foxglove: (ws://127\\.0\\.0\\.1:\\d+)");
    private static final ObjectMapper MAPPER = new ObjectMapper();

    @TempDir
    Path dir;

    private String peers;
    private final ByteArrayOutputStream stdout = new ByteArrayOutputStream();
    private PrintStream saved;

    @BeforeEach
    void captureStdout() {
        peers = NpmPeers.folder();
        saved = System.out;
        System.setOut(new PrintStream(stdout, true, StandardCharsets.UTF_8));
    }

    @AfterEach
    void restoreStdout() {
        if (saved != null) {
            System.setOut(saved);
        }
    }

    @Test
    void runStreamsEveryChannelOfARecordingAndTheClientDecodesEveryMessageSent() throws Exception {
        Path scenario = Path.of(Objects.requireNonNull(getClass().getResource("/scenarios/short-leg.yaml")).toURI());
        Path out = dir.resolve("run");
        // Time scale 2: about 8 s of wall time, for the client to connect while the robot drives.
        Command run = Command.start("rtaware-run-under-test", "run", "--scenario", scenario.toString(),
                "--time-scale", "2", "--out", out.toString(), "--quiet", "--seed", "7", "--foxglove", "0");
        JsonNode seen = watch(awaitUrl(run));
        assertEquals(0, run.result.get(120, TimeUnit.SECONDS), "the run's exit status; output:\n" + stdout);
        JsonNode foxglove = sentAsSeen(seen, MAPPER.readTree(out.resolve("report.json").toFile()));
        assertTrue(foxglove.path("address").asText().startsWith("127.0.0.1:"), "loopback: " + foxglove);
        JsonNode topics = seen.path("topics");
        assertTrue(topics.path("/scan").asLong() > 10, "scans streamed: " + topics);
        assertEquals(1, topics.path("/tf_static").asLong(), "the latched /tf_static, once: " + topics);
        assertTrue(topics.path("/map").asLong() >= 1, "the map: " + topics);
        for (String task : new String[] {"waypoint", "obstacle", "occupancy", "planner", "mediator"}) {
            assertTrue(topics.has("/rtaware/timing/" + task), "the timing channel of " + task + ": " + topics);
        }
        assertTrue(topics.path("/rtaware/timing/obstacle").asLong() > 10, "obstacle cycles streamed: " + topics);
        for (String topic : FoxgloveLayoutCheck.topics(FoxgloveLayoutCheck.shipped(), Map.of())) {
            assertTrue(topics.path(topic).asLong() > 0, "the shipped layout's " + topic + " streamed live: " + topics);
        }
        assertEquals("rtaware run", seen.path("server").asText(), seen.toString());
    }

    @Test
    void benchStreamsItsTimingChannels() throws Exception {
        Path report = dir.resolve("bench.json");
        Command bench = Command.start("rtaware-bench-under-test", "bench", "--tasks", "2", "--period", "10ms",
                "--work", "1ms", "--duration", "4s", "--quiet", "--json", report.toString(), "--foxglove", "0");
        JsonNode seen = watch(awaitUrl(bench));
        assertEquals(0, bench.result.get(120, TimeUnit.SECONDS), "the bench's exit status; output:\n" + stdout);
        sentAsSeen(seen, MAPPER.readTree(report.toFile()));
        JsonNode topics = seen.path("topics");
        assertTrue(topics.path("/rtaware/timing/t1").asLong() > 10, "t1's cycles streamed: " + topics);
        assertTrue(topics.has("/rtaware/timing/t2"), "t2's timing channel: " + topics);
        assertEquals("rtaware bench", seen.path("server").asText(), seen.toString());
    }

    @Test
    void simStreamsTheRobotAsARos2RobotUntilStopped() throws Exception {
        Command sim = Command.start("rtaware-sim-under-test", "sim", "--port", "0", "--time-scale", "5",
                "--foxglove", "0");
        JsonNode seen;
        try {
            seen = watch(awaitUrl(sim), "20");
        } finally {
            sim.thread.interrupt(); // what Ctrl-C does to sim: it serves until interrupted
        }
        assertEquals(0, sim.result.get(60, TimeUnit.SECONDS), "sim's exit status; output:\n" + stdout);
        JsonNode topics = seen.path("topics");
        assertTrue(topics.path("/scan").asLong() >= 20, "scans: " + topics);
        assertEquals(1, topics.path("/tf_static").asLong(), "the latched /tf_static, once: " + topics);
        assertEquals(1, topics.path("/map").asLong(), "the scenario's walls, latched: " + topics);
        assertTrue(topics.path("/odom").asLong() > 0 && topics.path("/ground_truth").asLong() > 0
                && topics.path("/tf").asLong() > 0, "odometry, ground truth, transforms: " + topics);
        assertEquals("rtaware sim", seen.path("server").asText(), seen.toString());
    }

    /**
     * {@code sim --ros2 --foxglove}: while Foxglove's client watches the scans, an independent ROS 2
     * node (ros2_peer.py: eclipse-zenoh and zenoh-ros2-sdk) connected to the simulator's Zenoh
     * endpoint decodes /scan and /odom, checks the frames and drives the robot on /cmd_vel.
     */
    @Test
    @Requires(NativeZenohLayer.class)
    void simServesFoxgloveAndRos2AtOnce() throws Exception {
        String python = PythonPeers.python();
        Path script = Ros2PythonPeer.script(dir);
        String endpoint = Ros2Wiring.freeLoopbackEndpoint();
        Command sim = Command.start("rtaware-sim-under-test", "sim", "--port", "0", "--ros2", "--listen", endpoint,
                "--foxglove", "0");
        JsonNode seen;
        JsonNode ros2Seen;
        try {
            String url = awaitUrl(sim);
            Process peer = new ProcessBuilder(python, script.toString(), "check", "--router", endpoint,
                    "--timeout", "60").redirectError(ProcessBuilder.Redirect.INHERIT).start();
            seen = watch(url, "20");
            String output = new String(peer.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
            assertTrue(peer.waitFor(90, TimeUnit.SECONDS), "the ROS 2 peer finished");
            ros2Seen = MAPPER.readTree(output.lines().reduce((a, b) -> b).orElse("{}"));
            assertEquals(0, peer.exitValue(), "the ROS 2 peer's checks: " + ros2Seen.path("failures")
                    + "\nsim's output:\n" + stdout);
        } finally {
            sim.thread.interrupt();
        }
        assertEquals(0, sim.result.get(60, TimeUnit.SECONDS), "sim's exit status; output:\n" + stdout);
        assertTrue(seen.path("topics").path("/scan").asLong() >= 20, "Foxglove's scans: " + seen);
        assertTrue(ros2Seen.path("first_scan").path("beams").asInt() > 100, "the ROS 2 peer's scan: " + ros2Seen);
        assertEquals("rtaware_sim", ros2Seen.path("scan_publishers").path(0).path("node").asText(), ros2Seen.toString());
        assertTrue(stdout.toString(StandardCharsets.UTF_8).contains("ROS 2 robot node"), "sim said so:\n" + stdout);
    }

    /** Asserts that the client saw exactly what the server counted as sent; returns the section. */
    private static JsonNode sentAsSeen(JsonNode seen, JsonNode report) {
        JsonNode foxglove = report.path(FoxgloveMixin.SECTION);
        assertEquals(seen.path("total").asLong(), foxglove.path("messages_sent").asLong(),
                "the client got exactly what the server counted as sent: " + seen + " vs " + foxglove);
        assertEquals(0, foxglove.path("messages_dropped").asLong(), "a local client keeps up: " + foxglove);
        assertEquals(1, foxglove.path("clients_accepted").asLong(), foxglove.toString());
        return foxglove;
    }

    /** A command run in this JVM on a thread of its own (the common pool has one thread on 2 cores). */
    private record Command(Thread thread, CompletableFuture<Integer> result) {
        static Command start(String name, String... args) {
            CompletableFuture<Integer> result = new CompletableFuture<>();
            Thread thread = new Thread(() -> {
                try {
                    result.complete(RtawareCli.execute(args));
                } catch (RuntimeException | Error e) {
                    result.completeExceptionally(e);
                }
            }, name);
            thread.setDaemon(true);
            thread.start();
            return new Command(thread, result);
        }
    }

    /** Runs Foxglove's client against the server; returns the counts it printed. */
    private JsonNode watch(String url, String... extra) throws Exception {
        List<String> command = new ArrayList<>(List.of("node", "src/test/node/check_foxglove_live.mjs", url));
        command.addAll(List.of(extra));
        Process node;
        try {
            ProcessBuilder pb = new ProcessBuilder(command).redirectErrorStream(true);
            pb.environment().put(NpmPeers.VARIABLE, peers);
            node = pb.start();
        } catch (IOException e) {
            throw new AssertionError("cannot run node: " + e.getMessage(), e);
        }
        String output = new String(node.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(node.waitFor(300, TimeUnit.SECONDS), "the client finished");
        assertEquals(0, node.exitValue(), "Foxglove's client checked every message:\n" + output
                + "\ncommand output:\n" + stdout);
        String counts = output.lines().filter(l -> l.startsWith("counts: ")).findFirst()
                .orElseThrow(() -> new AssertionError("no counts line:\n" + output)).substring("counts: ".length());
        return MAPPER.readTree(counts);
    }

    private String awaitUrl(Command command) throws Exception {
        Matcher m = URL.matcher("");
        Waits.until(() -> m.reset(stdout.toString(StandardCharsets.UTF_8)).find() || command.result.isDone(),
                Duration.ofSeconds(60), () -> "a 'foxglove: ws://...' line; output:\n" + stdout);
        if (!m.reset(stdout.toString(StandardCharsets.UTF_8)).find()) {
            throw new AssertionError("the run ended without a 'foxglove: ws://...' line; output:\n" + stdout);
        }
        return m.group(1);
    }
}
