package io.rtaware.app.ros2;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import io.rtaware.app.RtawareCli;
import io.rtaware.core.testing.Requires;
import io.rtaware.core.testing.Waits;
import io.rtaware.record.RecordingPlan;
import io.rtaware.record.mcap.McapChannel;
import io.rtaware.record.mcap.McapReader;
import io.rtaware.record.mcap.McapVisitor;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.ros2.task.Ros2DataTask;
import io.rtaware.ros2msg.LaserScanCodec;
import io.rtaware.ros2msg.Ros2Header;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.zenoh.NativeZenohLayer;
import io.rtaware.zenoh.ZenohLibrary;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code run --ros2} and {@code sim --ros2} over Zenoh on loopback, Java to Java: the controller
 * drives the short course through the ROS 2 data task. Checks outcome and report, not timing.
 */
@Timeout(180)
public class Ros2RunEndToEndTest {

    @TempDir
    Path dir;

    private Path shortLeg() throws Exception {
        return Path.of(Objects.requireNonNull(getClass().getResource("/scenarios/short-leg.yaml")).toURI());
    }

    private static JsonNode completedReport(Path out, String measuredOn) throws Exception {
        return completedReport(out, measuredOn, "kilted");
    }

    private static JsonNode completedReport(Path out, String measuredOn, String distro) throws Exception {
        JsonNode report = new ObjectMapper().readTree(out.resolve("report.json").toFile());
        JsonNode run = report.path("run");
        assertEquals("completed", run.path("outcome").asText(), "outcome; run section: " + run);
        assertEquals(measuredOn, run.path("measured_on").asText());
        assertTrue(run.path("distance_travelled_m").asDouble() > 1.5, "the robot drove the leg: " + run);
        boolean ros2Task = false;
        for (JsonNode t : report.path("tasks")) {
            ros2Task |= t.path("name").asText().equals("ros2") && t.path("runs").asLong() > 0;
        }
        assertTrue(ros2Task, "the ROS 2 data task ran and is reported");
        JsonNode ros2 = report.path("ros2");
        assertTrue(ros2.isObject(), "a ros2 section: " + report.fieldNames());
        assertEquals(distro, ros2.path("ros_distro").asText(), "the rmw_zenoh conventions followed: " + ros2);
        assertTrue(report.path("player").isMissingNode(), "no player section for a ROS 2 robot");
        assertTrue(ros2.path("scans").asLong() > 0 && ros2.path("odometry").asLong() > 0, "ros2: " + ros2);
        assertTrue(ros2.path("fault").isNull(), "no fault: " + ros2);
        assertTrue(ros2.path("rejected_samples").has(measuredOn.equals("odometry") ? "/robot1/scan" : "/scan"),
                "rejected samples by fully qualified topic: " + ros2);
        assertTrue(ros2.path("scan_latency_ms").has("p50") && ros2.path("scan_latency_ms").has("p99"), "ros2: " + ros2);
        assertEquals("rmw_zenoh", ros2.path("transport").asText(), "ros2: " + ros2);
        assertEquals(Ros2DataTask.LATENCY_FROM_ATTACHMENT, ros2.path("scan_latency_from").asText(), "ros2: " + ros2);
        assertTrue(ros2.path("cpu_us_per_sample").asDouble() > 0, "ros2: " + ros2);
        assertEquals(0, ros2.path("clock_epochs").asLong(-1), "one clock, no epochs: " + ros2);
        assertEquals(0, ros2.path("other_publisher_samples").asLong(-1), "one publisher per topic: " + ros2);
        assertTrue(ros2.path("notices").isArray() && ros2.path("notices").isEmpty(), "nothing to report once: " + ros2);
        return report;
    }

    private static int quietly(String... args) {
        PrintStream saved = System.out;
        try {
            System.setOut(new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8));
            return RtawareCli.execute(args);
        } finally {
            System.setOut(saved);
        }
    }

    @Test
    @Requires(NativeZenohLayer.class)
    void runRos2DrivesTheBuiltInSimulatorAsARos2Robot() throws Exception {
        Path out = dir.resolve("run");
        Path recording = dir.resolve("run.mcap");
        int status = quietly("run", "--ros2", "--scenario", shortLeg().toString(), "--time-scale", "10",
                "--out", out.toString(), "--quiet", "--seed", "7", "--record", recording.toString());
        assertEquals(0, status);
        completedReport(out, "ground_truth");
        assertScansStampedAtTheirFirstBeam(recording);
    }

    /**
     * Every recorded scan's header stamp, back on the simulator's clock, is the start of a sweep of
     * the URG-04LX (on its 100 ms turn grid), as sim --ros2 stamps it and the data task passes it on.
     */
    private static void assertScansStampedAtTheirFirstBeam(Path recording) throws Exception {
        List<Long> stamps = new ArrayList<>();
        LaserScanCodec codec = new LaserScanCodec();
        Ros2Header header = new Ros2Header();
        LaserScan scan = new LaserScan();
        RunMetadata file = new RunMetadata() {
            @Override
            public void message(McapChannel channel, long sequence, long logTimeNs, long publishTimeNs, byte[] data,
                                int offset, int length) {
                if (channel.topic().equals("/scan")) {
                    codec.decode(new CdrReader().wrap(data, offset, length), header, scan);
                    stamps.add(header.stampNs);
                }
            }
        };
        McapReader.open(recording).read(file);
        Map<String, String> run = file.run;
        assertEquals(RecordingPlan.STAMPS_MEASURED, run.get(RecordingPlan.HEADER_STAMPS), "metadata: " + run);
        long originNs = Long.parseLong(run.get(RecordingPlan.LOG_TIME_OFFSET_NS))
                + Long.parseLong(run.get(RecordingPlan.ROBOT_CLOCK_ORIGIN_NS));
        assertTrue(stamps.size() > 10, "scans recorded: " + stamps.size());
        for (long stampNs : stamps) {
            assertEquals(0, (stampNs - originNs) % 100_000_000L, "a scan stamped at the start of its sweep, "
                    + (stampNs - originNs) + " ns of simulated time");
        }
    }

    @Test
    @Requires(NativeZenohLayer.class)
    void runRos2WithHumbleConventionsDrivesTheBuiltInSimulatorAndSaysSoInTheReport() throws Exception {
        Path out = dir.resolve("humble");
        int status = quietly("run", "--ros2", "--ros-distro", "humble", "--scenario", shortLeg().toString(),
                "--time-scale", "10", "--out", out.toString(), "--quiet", "--seed", "7");
        assertEquals(0, status);
        completedReport(out, "ground_truth", "humble");
    }

    @Test
    @Requires(NativeZenohLayer.class)
    void runRos2DrivesASimulatorServingRos2InAnotherSession() throws Exception {
        int port;
        try (ServerSocket s = new ServerSocket(0)) {
            port = s.getLocalPort();
        }
        String endpoint = "tcp/127.0.0.1:" + port;
        AtomicInteger simStatus = new AtomicInteger(-1);
        Thread sim = new Thread(() -> simStatus.set(RtawareCli.execute("sim", "--ros2", "--listen", endpoint,
                "--port", "0", "--scenario", shortLegUnchecked(), "--time-scale", "10", "--seed", "7",
                "--namespace", "/robot1")), "sim --ros2");
        sim.start();
        try {
            Path out = dir.resolve("run");
            Path recording = dir.resolve("external.mcap");
            int status = -1;
            // The simulator binds its endpoint asynchronously: an unreachable router is exit 2, retry.
            for (int attempt = 0; attempt < 50 && status != 0; attempt++) {
                status = quietly("run", "--ros2", "--zenoh", endpoint, "--namespace", "/robot1", "--scenario",
                        shortLegUnchecked(), "--time-scale", "10", "--out", out.toString(), "--quiet",
                        "--record", recording.toString());
                assertTrue(status == 0 || status == 2, "exit status " + status);
                assertTrue(sim.isAlive(), "the simulator is serving (its exit status: " + simStatus.get() + ")");
            }
            assertEquals(0, status);
            completedReport(out, "odometry");
            assertRecordedAsAnExternalRobot(recording, "ROS 2 robot through Zenoh at " + endpoint);
        } finally {
            sim.interrupt();
            sim.join(10_000);
        }
    }

    /**
     * A robot reached through a router is not known to be the simulator: the file has no
     * {@code /ground_truth} (the referee watched odometry, which is not truth), names the robot as
     * it was reached, and gives the model only as the controller's assumption.
     */
    private static void assertRecordedAsAnExternalRobot(Path recording, String robot) throws Exception {
        RunMetadata file = new RunMetadata();
        McapReader.open(recording).read(file);
        List<String> topics = file.topics;
        Map<String, String> run = file.run;
        assertTrue(topics.contains("/odom") && !topics.contains("/ground_truth"), "no ground truth: " + topics);
        assertEquals(robot, run.get("robot"), "metadata: " + run);
        assertEquals(null, run.get("robot_model"), "metadata: " + run);
        assertEquals("koala", run.get("assumed_robot_model"), "metadata: " + run);
    }

    /** A recording's {@code rtaware.run} metadata and its channels' topics; messages are read by subclasses. */
    private static class RunMetadata implements McapVisitor {
        final Map<String, String> run = new HashMap<>();
        final List<String> topics = new ArrayList<>();

        @Override
        public void metadata(String name, Map<String, String> entries) {
            if (name.equals("rtaware.run")) {
                run.putAll(entries);
            }
        }

        @Override
        public void channel(McapChannel channel) {
            topics.add(channel.topic());
        }

        @Override
        public void message(McapChannel channel, long sequence, long logTimeNs, long publishTimeNs, byte[] data,
                            int offset, int length) {
            // the metadata and the channels are what this reads
        }
    }

    @Test
    @Requires(NativeZenohLayer.class)
    void aRos2RobotThatSendsNanPosesIsHaltedAndTheRunEndsAsAnError() throws Exception {
        String endpoint;
        try (ServerSocket s = new ServerSocket(0)) {
            endpoint = "tcp/127.0.0.1:" + s.getLocalPort();
        }
        Path out = dir.resolve("nan");
        ByteArrayOutputStream stderr = new ByteArrayOutputStream();
        PrintStream savedErr = System.err;
        int status;
        ScriptedRos2Robot robot = ScriptedRos2Robot.nanPosesAfter(endpoint, 500);
        try {
            System.setErr(new PrintStream(stderr, true, StandardCharsets.UTF_8));
            status = quietly("run", "--ros2", "--zenoh", endpoint, "--scenario", shortLeg().toString(),
                    "--time-scale", "1", "--out", out.toString(), "--quiet");
            Waits.until(() -> robot.lastTwist() != null && robot.lastTwist().isStop(), Duration.ofSeconds(10),
                    "a zero Twist, the last the robot received");
        } finally {
            System.setErr(savedErr);
            robot.close();
        }
        String err = stderr.toString(StandardCharsets.UTF_8);
        assertEquals(null, robot.failure(), "the test robot ran");
        assertTrue(robot.drove() && robot.poisoned(), "driven, then sent NaN poses");
        assertEquals(1, status, "stderr: " + err);
        assertEquals(1, err.lines().filter(l -> l.contains("ROS 2 topic /odom sent only impossible samples")).count(),
                "one line names the topic: " + err);
        assertTrue(err.contains("x = NaN"), "and the value: " + err);
        JsonNode report = new ObjectMapper().readTree(out.resolve("report.json").toFile());
        JsonNode run = report.path("run");
        assertEquals("error", run.path("outcome").asText(), "run section: " + run);
        assertTrue(run.path("reason").asText().startsWith("ROS 2 topic /odom sent only impossible samples"), run.toString());
        JsonNode ros2 = report.path("ros2");
        assertTrue(ros2.path("fault").asText().contains("x = NaN"), "ros2: " + ros2);
        assertTrue(ros2.path("rejected_samples").path("/odom").asLong() > 0, "ros2: " + ros2);
        assertEquals(0, ros2.path("rejected_samples").path("/scan").asLong(), "ros2: " + ros2);
        assertTrue(report.path("player").isMissingNode(), "no player section for a ROS 2 robot");
        boolean ros2Errors = false;
        for (JsonNode t : report.path("tasks")) {
            ros2Errors |= t.path("name").asText().equals("ros2") && t.path("errors").asLong() >= 1;
        }
        assertTrue(ros2Errors, "the halt is counted as an error of the ros2 task");
    }

    private String shortLegUnchecked() {
        try {
            return shortLeg().toString();
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }

    @Test
    @Requires(NativeZenohLayer.class)
    void unreachableRouterIsOneLineAndExitTwo() throws Exception {
        int port;
        try (ServerSocket s = new ServerSocket(0)) {
            port = s.getLocalPort();
        }
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        PrintStream saved = System.err;
        int status;
        try {
            System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
            status = RtawareCli.execute("run", "--ros2", "--zenoh", "tcp/127.0.0.1:" + port, "--quiet",
                    "--out", dir.resolve("x").toString());
        } finally {
            System.setErr(saved);
        }
        String text = err.toString(StandardCharsets.UTF_8);
        assertEquals(2, status, text);
        assertEquals(1, text.lines().count(), "one line: " + text);
        assertTrue(text.contains("tcp/127.0.0.1:" + port), text);
    }

    @Test
    void malformedEndpointsAndStrayOptionsAreUserErrors() {
        assertEquals(2, quietly("run", "--ros2", "--zenoh", "localhost:7447", "--quiet"));
        assertEquals(2, quietly("run", "--zenoh", "tcp/127.0.0.1:7447", "--quiet"));
        assertEquals(2, quietly("run", "--ros2", "--domain", "300", "--quiet"));
        assertEquals(2, quietly("sim", "--ros2", "--listen", "tcp/0.0.0.0"));
        assertEquals(2, quietly("sim", "--listen", "tcp/127.0.0.1:0"));
    }

    @Test
    void anUnknownRosDistroOrOneWithoutRos2IsOneLineAndExitStatusTwo() {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        PrintStream saved = System.err;
        try {
            System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
            assertEquals(2, quietly("run", "--ros2", "--ros-distro", "iron", "--quiet"), "unknown distribution");
            assertEquals(2, quietly("sim", "--ros-distro", "jazzy"), "--ros-distro without --ros2");
            assertEquals(2, quietly("bench", "--ros-distro", "iron", "--export", "--duration", "1s"), "bench --export");
        } finally {
            System.setErr(saved);
        }
        List<String> lines = err.toString(StandardCharsets.UTF_8).lines().toList();
        assertEquals(3, lines.size(), "one line each: " + lines);
        assertTrue(lines.get(0).contains("--ros-distro: unknown ROS 2 distribution 'iron' (expected one of humble, "
                + "jazzy, kilted, rolling)"), lines.get(0));
        assertTrue(lines.get(1).contains("--ros-distro needs --ros2"), lines.get(1));
        assertTrue(lines.get(2).contains("'iron'"), lines.get(2));
    }

    @Test
    void withoutTheNativeLayerRos2SaysHowToEnableIt() {
        String reason = ZenohLibrary.unavailableReason();
        assumeTrue(reason != null, "the native Zenoh layer is present here");
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        PrintStream saved = System.err;
        try {
            System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
            assertEquals(2, RtawareCli.execute("run", "--ros2", "--quiet"));
        } finally {
            System.setErr(saved);
        }
        assertTrue(err.toString(StandardCharsets.UTF_8).contains("install Rust"), err.toString(StandardCharsets.UTF_8));
    }
}
