package io.rtaware.app.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeFalse;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import io.rtaware.app.CliRun;
import io.rtaware.app.RtawareCli;
import io.rtaware.app.foxglove.FoxgloveLayoutCheck;
import io.rtaware.core.testing.PythonPeers;
import io.rtaware.record.RecordingPlan;
import io.rtaware.record.StateJsonMessage;
import io.rtaware.record.mcap.McapChannel;
import io.rtaware.record.mcap.McapReader;
import io.rtaware.record.mcap.McapSchema;
import io.rtaware.record.mcap.McapSummary;
import io.rtaware.record.mcap.McapVisitor;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.ros2msg.LaserScanCodec;
import io.rtaware.ros2msg.Ros2Header;
import io.rtaware.ros2msg.TransformMessages;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.value.PlanarPose;
import java.io.BufferedReader;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code run --record} end to end: a short course recorded, read back by rtaware's own reader and
 * by the independent Python readers (when {@code RTAWARE_PEER_PYTHON} names a Python with
 * mcap and mcap-ros2-support: .ci/run sets it up), and a real process interrupted with SIGINT
 * that still leaves a complete file.
 */
class RecordRunTest {

    @TempDir
    static Path dir;
    private static Path recording;
    private static Path out;
    private static String printed;

    @BeforeAll
    static void recordAShortRun() throws Exception {
        Path scenario = Path.of(Objects.requireNonNull(RecordRunTest.class.getResource("/scenarios/short-leg.yaml")).toURI());
        out = dir.resolve("run");
        recording = dir.resolve("run.mcap");
        PrintStream saved = System.out;
        ByteArrayOutputStream stdout = new ByteArrayOutputStream();
        int status;
        try {
            System.setOut(new PrintStream(stdout, true, StandardCharsets.UTF_8));
            status = RtawareCli.execute("run", "--scenario", scenario.toString(), "--time-scale", "10",
                    "--out", out.toString(), "--quiet", "--seed", "7", "--record", recording.toString());
        } finally {
            System.setOut(saved);
        }
        printed = stdout.toString(StandardCharsets.UTF_8);
        assertEquals(0, status, printed);
    }

    @Test
    void ownReaderReadsTheRecordingAndTheReportCountsIt() throws Exception {
        McapReader reader = McapReader.open(recording);
        McapSummary summary = reader.summary();
        Map<String, Integer> counts = new HashMap<>();
        LaserScan scan = new LaserScan();
        Ros2Header header = new Ros2Header();
        CdrReader cdr = new CdrReader();
        LaserScanCodec codec = new LaserScanCodec();
        Map<String, String> run = new HashMap<>();
        Map<Long, Long> scanStamps = new HashMap<>();
        Map<Long, Double> scanTimesS = new HashMap<>();
        long[] measuredBeforeCommit = new long[1];
        ObjectMapper json = new ObjectMapper();
        reader.read(new McapVisitor() {
            @Override
            public void metadata(String name, Map<String, String> entries) {
                if (name.equals("rtaware.run")) {
                    run.putAll(entries);
                }
            }

            @Override
            public void message(McapChannel channel, long sequence, long logTimeNs, long publishTimeNs,
                                byte[] data, int offset, int length) {
                counts.merge(channel.topic(), 1, Integer::sum);
                if (channel.topic().equals("/scan")) {
                    codec.decode(cdr.wrap(data, offset, length), header, scan);
                    assertTrue(header.stampNs <= logTimeNs, "stamped when measured, by the commit at the latest");
                    measuredBeforeCommit[0] += header.stampNs < logTimeNs ? 1 : 0;
                    scanStamps.put(sequence, header.stampNs);
                    assertTrue(scan.count() > 100, "beams: " + scan.count());
                } else if (channel.topic().equals("/rtaware/state/laser")) {
                    try {
                        scanTimesS.put(sequence, json.readTree(StateJsonMessage.json(data, offset, length))
                                .get("serverTimeS").asDouble());
                    } catch (IOException e) {
                        throw new AssertionError(e);
                    }
                }
            }
        });
        assertEquals(RecordingPlan.STAMPS_MEASURED, run.get(RecordingPlan.HEADER_STAMPS), "the simulator's clock is known");
        long stampOffsetNs = Long.parseLong(run.get(RecordingPlan.LOG_TIME_OFFSET_NS))
                + Long.parseLong(run.get(RecordingPlan.ROBOT_CLOCK_ORIGIN_NS));
        assertEquals(scanTimesS.keySet(), scanStamps.keySet(), "a state message per scan");
        scanStamps.forEach((generation, stampNs) -> assertEquals(
                stampOffsetNs + Math.round(scanTimesS.get(generation) * 1e9), stampNs,
                "scan " + generation + " stamped with the simulator's timestamp on the run's clock"));
        assertTrue(measuredBeforeCommit[0] > 0, "scans measured before their commit");
        assertTrue(counts.getOrDefault("/clock", 0) > 0, "/clock on the simulator's time: " + counts);
        for (String topic : new String[] {"/scan", "/odom", "/cmd_vel", "/map", "/plan", "/ground_truth",
            "/rtaware/events", "/rtaware/timing/planner", "/rtaware/timing/player", "/rtaware/data/course"}) {
            assertTrue(summary.channels().stream().anyMatch(c -> c.topic().equals(topic)), "channel " + topic);
        }
        assertTrue(counts.getOrDefault("/scan", 0) > 10, "scans recorded: " + counts);
        long total = counts.values().stream().mapToLong(Integer::longValue).sum();
        assertEquals(summary.statistics().messageCount(), total);

        JsonNode report = new ObjectMapper().readTree(out.resolve("report.json").toFile());
        assertEquals(total, report.path("recording").path("messages").asLong(), "report.json recording section");
        assertEquals(Files.size(recording), report.path("recording").path("bytes").asLong());
        assertTrue(report.path("recording").has("dropped"));
        assertTrue(printed.contains("recording written to"), printed);
    }

    @Test
    void inspectSummarizesTheRecordingAndPlotsLateness() throws Exception {
        Path png = dir.resolve("plots/lateness.png");
        PrintStream saved = System.out;
        ByteArrayOutputStream stdout = new ByteArrayOutputStream();
        int status;
        try {
            System.setOut(new PrintStream(stdout, true, StandardCharsets.UTF_8));
            status = RtawareCli.execute("inspect", recording.toString(), "--plot", png.toString());
        } finally {
            System.setOut(saved);
        }
        String text = stdout.toString(StandardCharsets.UTF_8);
        assertEquals(0, status, text);
        assertTrue(text.contains("sensor_msgs/msg/LaserScan"), text);
        assertTrue(text.contains("task timing"), text);
        long plannerRuns = new ObjectMapper().readTree(out.resolve("report.json").toFile()).path("tasks").findValues("name")
                .stream().filter(n -> n.asText().equals("planner")).count();
        assertEquals(1, plannerRuns);
        assertTrue(text.lines().anyMatch(l -> l.startsWith("planner ")), "a timing row per task:\n" + text);
        // Issue 34: inspect's words count what run's count (inspect said 'miss 57' where run said 'misses 390').
        assertTrue(text.lines().anyMatch(l -> l.matches("task +releases +runs +misses +missed runs +skipped +stale +errors .*")),
                "the run's words, in the run's order:\n" + text);
        JsonNode tasks = new ObjectMapper().readTree(out.resolve("report.json").toFile()).path("tasks");
        for (JsonNode task : tasks) {
            String[] row = text.lines().filter(l -> l.startsWith(task.path("name").asText() + " ")).findFirst()
                    .orElseThrow().trim().split("\\s+");
            String name = task.path("name").asText();
            assertEquals(task.path("releases").asLong(), Long.parseLong(row[1]), "releases of " + name + ": " + text);
            assertEquals(task.path("runs").asLong(), Long.parseLong(row[2]), "runs of " + name);
            assertEquals(task.path("misses").asLong(), Long.parseLong(row[3]), "misses of " + name);
            assertEquals(task.path("skipped").asLong(), Long.parseLong(row[5]), "skipped of " + name);
            assertEquals(Long.parseLong(row[3]), Long.parseLong(row[4]) + Long.parseLong(row[5]),
                    "misses = missed runs + skipped: " + name);
            assertEquals(task.path("stale_runs").asLong(), Long.parseLong(row[6]), "stale runs of " + name);
            assertEquals(task.path("errors").asLong(), Long.parseLong(row[7]), "errors of " + name);
        }
        assertTrue(Files.size(png) > 1000, "plot written");
        assertEquals(2, RtawareCli.execute("inspect", out.resolve("report.json").toString()), "not MCAP: user error");
        assertEquals(2, RtawareCli.execute("inspect", dir.resolve("none.mcap").toString()), "missing: user error");
    }

    /** Issue 24: --plot NAME wrote NAME.png and said NAME; /dev/full got /dev/full.png, '' got ./.png. */
    @Test
    void thePlotIsWrittenWhereTheUserSaidOrTheFailureIsOneLine() throws Exception {
        Path named = dir.resolve("plots/lateness-without-extension");
        CliRun plotted = CliRun.of("inspect", recording.toString(), "--plot", named.toString());
        assertEquals(0, plotted.status(), plotted.toString());
        assertTrue(plotted.out().contains("lateness plot written to " + named), plotted.out());
        assertTrue(Files.size(named) > 1000, "written under the name given");
        assertTrue(Files.notExists(Path.of(named + ".png")), "and under no other");
        CliRun.of("inspect", recording.toString(), "--plot", "").assertOneLineUserError("--plot must name a file");
        CliRun full = CliRun.of("inspect", recording.toString(), "--plot", "/dev/full");
        assertEquals(1, full.status(), full.toString());
        assertTrue(full.err().contains("could not write /dev/full"), full.err());
        assertTrue(Files.notExists(Path.of("/dev/full.png")), "nothing beside the device");
    }

    @Test
    void independentPythonReadersDecodeEveryRos2MessageAndAgreeWithTheRun() throws Exception {
        String python = PythonPeers.python();
        Process p = new ProcessBuilder(python, "src/test/python/check_recording.py", recording.toString(), out.toString())
                .redirectErrorStream(true).start();
        String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "checker finished");
        assertEquals(0, p.exitValue(), output);
        assertTrue(output.contains("/scan messages"), output);
    }

    @Test
    void rosToolsReadTheRecordingAsAnMcapRos2ProfileBagInLogTimeOrder() throws Exception {
        String output = Ros2ProfileCheck.run(recording);
        assertTrue(output.contains("rosbags AnyReader deserialized all"), output);
        assertTrue(output.contains("deadline_misses of every task (mediator, obstacle, occupancy, planner, player, "
                + "waypoint)"), "issue 37: /statistics of every task of the robot run, every second: " + output);
    }

    @Test
    void foxglovesReadersDecodeEveryMessageIndexedAndStreamed() throws Exception {
        String output = FoxgloveReadersCheck.run(recording);
        assertTrue(output.contains("McapIndexedReader decoded all"), output);
        assertTrue(output.contains("McapStreamReader decoded all"), output);
    }

    /** Linux: bit 2 (SIGINT) of the SigIgn mask in /proc/self/status. */
    private static boolean sigintIgnoredHere() throws IOException {
        Path status = Path.of("/proc/self/status");
        if (!Files.isReadable(status)) {
            return false;
        }
        for (String line : Files.readAllLines(status)) {
            if (line.startsWith("SigIgn:")) {
                return (Long.parseUnsignedLong(line.substring("SigIgn:".length()).strip(), 16) & 0x2L) != 0;
            }
        }
        return false;
    }

    /** The recording's channels by topic, with their schemas. */
    private static Map<String, FoxgloveLayoutCheck.Channel> channels() throws IOException {
        McapSummary summary = McapReader.open(recording).summary();
        Map<String, FoxgloveLayoutCheck.Channel> channels = new HashMap<>();
        for (McapChannel c : summary.channels()) {
            McapSchema schema = summary.schemas().stream().filter(s -> s.id() == c.schemaId()).findFirst().orElseThrow();
            assertEquals("ros2msg", schema.encoding(), c.topic());
            channels.put(c.topic(), new FoxgloveLayoutCheck.Channel(schema.name(), schema.data(),
                    c.metadata().get("frame_id")));
        }
        return channels;
    }

    /** Each frame's parent on the recording's {@code /tf} and {@code /tf_static}. */
    private static Map<String, String> parentOf() throws IOException {
        Map<String, String> parents = new HashMap<>();
        Ros2Header header = new Ros2Header();
        StringBuilder child = new StringBuilder();
        PlanarPose pose = new PlanarPose();
        McapReader.open(recording).read(new McapVisitor() {
            @Override
            public void message(McapChannel channel, long sequence, long logTimeNs, long publishTimeNs, byte[] data,
                                int offset, int length) {
                if (channel.topic().equals("/tf") || channel.topic().equals("/tf_static")) {
                    CdrReader in = new CdrReader().wrap(data, offset, length);
                    for (int i = TransformMessages.count(in); i > 0; i--) {
                        TransformMessages.read(in, header, child, pose);
                        parents.put(child.toString(), header.frameId.toString());
                    }
                }
            }
        });
        return parents;
    }

    /**
     * REP 105, one meaning per frame: the controller's map and plan are in its odometry frame
     * ({@code odom}), the truth in the world's ({@code world}), and no transform claims the two
     * are one (before, both were {@code map}, with an identity {@code map -> odom}).
     */
    @Test
    void framesFollowRep105WithOneMeaningEach() throws Exception {
        Map<String, FoxgloveLayoutCheck.Channel> channels = channels();
        assertEquals("odom", channels.get("/map").frameId(), "the controller's map is built on odometry");
        assertEquals("odom", channels.get("/plan").frameId(), "and planned on it");
        assertEquals("world", channels.get("/ground_truth").frameId(), "the truth is in the world's frame");
        assertEquals(Map.of("base_link", "odom", "laser", "base_link", "ground_truth", "world"), parentOf(),
                "two trees, odometry's and the world's, joined by nothing");
    }

    @Test
    void theShippedFoxgloveLayoutReadsOnlyTopicsAndFieldsTheRecordingAdvertises() throws Exception {
        JsonNode layout = FoxgloveLayoutCheck.shipped();
        Map<String, FoxgloveLayoutCheck.Channel> channels = channels();
        assertEquals(List.of(), FoxgloveLayoutCheck.problems(layout, channels, parentOf()));
        Set<String> read = FoxgloveLayoutCheck.topics(layout, channels);
        for (String task : List.of("player", "obstacle", "occupancy", "planner", "waypoint", "mediator")) {
            assertTrue(read.contains("/rtaware/timing/" + task), "every task of the run is plotted: " + read);
        }
        assertEquals(Set.of("/map", "/scan", "/plan", "/ground_truth", "/rtaware/timing/player", "/rtaware/timing/obstacle",
                "/rtaware/timing/occupancy", "/rtaware/timing/planner", "/rtaware/timing/waypoint",
                "/rtaware/timing/mediator", "/rtaware/data/mediator.decision", "/rosout", "/diagnostics"), read);
        assertEquals(12, layout.path("configById").path("Plot!lateness").path("paths").size()
                + layout.path("configById").path("Plot!exec").path("paths").size(), "lateness and exec of six tasks");
    }

    @Test
    void aLayoutNamingATopicOrFieldTheRecordingLacksFails() throws Exception {
        Map<String, FoxgloveLayoutCheck.Channel> channels = channels();
        ObjectNode layout = (ObjectNode) FoxgloveLayoutCheck.shipped();
        ObjectNode configs = (ObjectNode) layout.path("configById");
        ArrayNode lateness = (ArrayNode) configs.path("Plot!lateness").path("paths");
        ((ObjectNode) lateness.get(0)).put("value", "/rtaware/timing/player.latenes");
        ((ObjectNode) lateness.get(1)).put("value", "/rtaware/timing/steering.lateness");
        ((ObjectNode) lateness.get(2)).put("value", "/rtaware/timing/occupancy.input_generations");
        ((ObjectNode) lateness.get(3)).put("value", "/rtaware/timing/planner.outcome");
        ((ObjectNode) configs.path("StateTransitions!winner").path("paths").get(0))
                .put("value", "\"/rtaware/data/mediator.decision\".winner{stale==true}");
        ((ArrayNode) configs.path("Plot!exec").path("paths")).addObject().put("value", "/odom.pose.pose.position.w");
        ((ObjectNode) configs.path("3D!odom").path("topics")).putObject("/costmap");
        ((ObjectNode) configs.path("3D!world").path("topics")).putObject("/scan");
        ((ObjectNode) configs.path("3D!world")).put("followTf", "map");
        ((ObjectNode) configs.path("RosOut!events")).put("topicToRender", "/rtaware/events");
        ((ObjectNode) configs.path("Table!tasks")).put("topicPath", "/diagnostics.status.name");
        assertEquals(List.of(
                "3D!odom: topic /costmap is not advertised by the recording",
                "3D!world: display frame 'map' is no frame of the recording's transforms",
                "3D!world: /ground_truth is in frame 'world', which no transform places in the display frame 'map'",
                "3D!world: /scan is in frame 'laser', which no transform places in the display frame 'map'",
                "Plot!lateness: /rtaware/timing/player.latenes: no field 'latenes' in rtaware_msgs/msg/TaskCycle",
                "Plot!lateness: topic /rtaware/timing/steering is not advertised by the recording",
                "Plot!lateness: /rtaware/timing/occupancy.input_generations ends on int64[], not a value this panel draws",
                "Plot!lateness: /rtaware/timing/planner.outcome ends on string, not a value this panel draws",
                "Plot!exec: /odom.pose.pose.position.w: no field 'w' in geometry_msgs/Point",
                "StateTransitions!winner: \"/rtaware/data/mediator.decision\".winner{stale==true}: the filter {stale==true}"
                        + " names no field of uint8",
                "Table!tasks: /diagnostics.status.name: field name of an array without an index or slice",
                "RosOut!events: /rtaware/events is rtaware_msgs/msg/MonitorEvent, not a type the Log panel reads "
                        + FoxgloveLayoutCheck.LOG_TYPES), FoxgloveLayoutCheck.problems(layout, channels, parentOf()));
    }

    @Test
    void aRunInterruptedWithSigintLeavesACompleteRecording() throws Exception {
        assumeTrue(Files.isExecutable(Path.of("/bin/kill")) || Files.isExecutable(Path.of("/usr/bin/kill")),
                "no kill command to send SIGINT");
        assumeFalse(sigintIgnoredHere(), "SIGINT is ignored in this process (Maven was started as a background job"
                + " without job control), and a child inherits that, so it cannot be interrupted with SIGINT here;"
                + " run the build in the foreground");
        Path file = dir.resolve("interrupted.mcap");
        Path runDir = dir.resolve("interrupted");
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Process p = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"),
                RtawareCli.class.getName(), "run", "--time-scale", "5", "--out", runDir.toString(),
                "--record", file.toString()).redirectErrorStream(true).start();
        StringBuilder log = new StringBuilder();
        try (BufferedReader lines = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8))) {
            String line;
            boolean signalled = false;
            while ((line = lines.readLine()) != null) {
                log.append(line).append('\n');
                // The status line comes once the controller runs: interrupt it mid-course.
                if (!signalled && line.contains("rtaware run: scenario")) {
                    signalled = true;
                    Process kill = new ProcessBuilder("kill", "-INT", Long.toString(p.pid())).start();
                    assertEquals(0, kill.waitFor());
                }
            }
        }
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "the run ends after SIGINT:\n" + log);
        assertEquals(130, p.exitValue(), "exit status of an interrupted run:\n" + log);
        McapReader reader = McapReader.open(file);
        McapSummary summary = reader.summary();
        long[] read = {0};
        reader.read((channel, sequence, logTimeNs, publishTimeNs, data, offset, length) -> read[0]++);
        assertEquals(summary.statistics().messageCount(), read[0], "every message readable, CRCs valid");
        JsonNode report = new ObjectMapper().readTree(runDir.resolve("report.json").toFile());
        assertEquals("interrupted", report.path("run").path("outcome").asText());
        assertEquals(read[0], report.path("recording").path("messages").asLong());
    }
}
