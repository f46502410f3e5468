package io.rtaware.app.ros2;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import io.rtaware.app.RtawareCli;
import io.rtaware.core.testing.PythonPeers;
import io.rtaware.core.testing.Requires;
import io.rtaware.core.time.ScaledClock;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.ros2.graph.DdsSettings;
import io.rtaware.ros2.graph.Ros2Context;
import io.rtaware.ros2.graph.Ros2Distro;
import io.rtaware.ros2.task.Ros2DataTask;
import io.rtaware.sim.ros2.Ros2SimRobot;
import io.rtaware.sim.scenario.ScenarioLoader;
import io.rtaware.sim.server.PlayerSimServer;
import io.rtaware.sim.server.ServerConfig;
import io.rtaware.sim.server.SimCommandSupport;
import io.rtaware.zenoh.DdsBridgeBuilt;
import java.io.BufferedReader;
import java.io.ByteArrayOutputStream;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * ROS 2 over DDS (issue 29) against an independent implementation: a node written with Eclipse
 * Cyclone DDS's Python binding ({@code src/test/resources/ros2/dds_peer.py}) that behaves as a
 * stock ROS 2 node on the wire. It drives the simulator served over DDS, and it is the Cyclone DDS
 * robot that {@code run --ros2 --dds} drives through the paper's short leg (the simulator on one
 * DDS domain, relayed by the peer to another). All DDS traffic stays on the loopback interface,
 * multicast off, and every UDP socket on 127.0.0.1; each test has domains of its own, so that
 * tests never see each other's DDS traffic. Skipped without the bridge or the peer's Python, except under CI=true (with Rust),
 * where that fails.
 */
@Timeout(240)
class DdsEndToEndTest {

    @TempDir
    Path dir;

    private static final ObjectMapper JSON = new ObjectMapper();

    private Path peerScript() throws Exception {
        PythonPeers.python(); // with cyclonedds
        Path script = dir.resolve("dds_peer.py");
        try (InputStream in = Objects.requireNonNull(getClass().getResourceAsStream("/ros2/dds_peer.py"))) {
            Files.copy(in, script);
        }
        return script;
    }

    private static Process peer(Path script, String... args) throws Exception {
        List<String> command = new ArrayList<>(List.of(PythonPeers.python(), script.toString()));
        command.addAll(List.of(args));
        return new ProcessBuilder(command).redirectError(ProcessBuilder.Redirect.INHERIT).start();
    }

    private static JsonNode lastJsonLine(String output) throws Exception {
        return JSON.readTree(output.lines().reduce((a, b) -> b).orElse("{}"));
    }

    private static Ros2Context ddsContext(int domain) throws Exception {
        return Ros2Context.openDds(DdsSettings.loopback(domain, Ros2Distro.KILTED, Map.of()), 10_000);
    }

    private static PlayerSimServer simulator(String scenario, double timeScale) throws Exception {
        return SimCommandSupport.start(ScenarioLoader.load(scenario), new ScaledClock(timeScale), ServerConfig.defaults(0),
                7, 4);
    }

    private String shortLeg() throws Exception {
        return Path.of(Objects.requireNonNull(getClass().getResource("/scenarios/short-leg.yaml")).toURI()).toString();
    }

    @Test
    @Requires(DdsBridgeBuilt.class)
    void aCycloneDdsNodeReadsTheSimulatorOverDdsAndDrivesIt() throws Exception {
        Path script = peerScript();
        try (PlayerSimServer server = simulator("paper-room", 10);
             Ros2SimRobot robot = Ros2SimRobot.start(server, ddsContext(41), "/", line -> { })) {
            Pose2d start = server.groundTruth();
            Process node = peer(script, "drive", "--domain", "41", "--seconds", "8", "--speed", "0.3");
            String output = new String(node.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertTrue(node.waitFor(60, TimeUnit.SECONDS), "the Cyclone DDS node finished");
            JsonNode seen = lastJsonLine(output);
            assertEquals(0, node.exitValue(), "the node's checks: " + seen);
            assertTrue(seen.path("first_scan").path("beams").asInt() > 100, "LaserScan decoded over DDS: " + seen);
            assertEquals("laser", seen.path("first_scan").path("frame").asText(), "the scan's frame: " + seen);
            assertEquals("odom", seen.path("first_odometry").path("frame").asText(), "Odometry decoded: " + seen);
            assertEquals("base_link", seen.path("first_odometry").path("child").asText(), "its child frame: " + seen);
            assertTrue(seen.path("moved_m").asDouble() > 0.1, "odometry over DDS says the robot moved: " + seen);
            assertTrue(robot.commands() > 0, "the simulator obeyed the Cyclone DDS node's rt/cmd_vel");
            Pose2d end = server.groundTruth();
            assertTrue(Math.hypot(end.xM() - start.xM(), end.yM() - start.yM()) > 0.1,
                    "ground truth moved from " + start + " to " + end);
        }
    }

    @Test
    @Requires(DdsBridgeBuilt.class)
    void runRos2DdsCompletesTheShortLegAgainstACycloneDdsRobotAndStopsIt() throws Exception {
        Path script = peerScript();
        Path out = dir.resolve("run");
        try (PlayerSimServer server = simulator(shortLeg(), 10);
             Ros2SimRobot robot = Ros2SimRobot.start(server, ddsContext(42), "/", line -> { })) {
            Process relay = peer(script, "relay", "--from", "42", "--to", "43");
            JsonNode relayed;
            int status;
            try (BufferedReader relayOut = new BufferedReader(new InputStreamReader(relay.getInputStream(),
                    StandardCharsets.UTF_8))) {
                assertEquals("ready", relayOut.readLine(), "the Cyclone DDS robot started");
                status = quietly("run", "--ros2", "--dds", "--domain", "43", "--scenario", shortLeg(), "--time-scale",
                        "10", "--out", out.toString(), "--quiet");
                relay.getOutputStream().close();
                relayed = JSON.readTree(relayOut.readLine());
            } finally {
                if (!relay.waitFor(20, TimeUnit.SECONDS)) {
                    relay.destroyForcibly();
                }
            }
            assertEquals(0, status, "run --ros2 --dds exit status");
            assertEquals(0, relay.exitValue(), "every command the robot received was finite: " + relayed);
            assertTrue(relayed.path("scans").asLong() > 0 && relayed.path("odometry").asLong() > 0, "relayed: " + relayed);
            assertTrue(relayed.path("commands").asLong() > 0, "commands over DDS: " + relayed);
            assertEquals("[0.0,0.0]", relayed.path("last_command").toString(), "the run stopped the robot last");
            JsonNode report = JSON.readTree(out.resolve("report.json").toFile());
            assertEquals("completed", report.path("run").path("outcome").asText(), "run: " + report.path("run"));
            JsonNode ros2 = report.path("ros2");
            assertEquals("dds", ros2.path("transport").asText(), "ros2: " + ros2);
            assertTrue(ros2.path("robot").asText().contains("DDS domain 43 (loopback only, no multicast)"), "ros2: " + ros2);
            assertTrue(ros2.path("scans").asLong() > 0 && ros2.path("odometry").asLong() > 0, "ros2: " + ros2);
            assertTrue(ros2.path("fault").isNull(), "no fault: " + ros2);
            assertTrue(ros2.path("scan_latency_ms").isNull() && ros2.path("scan_latency_from").isNull(),
                    "the simulator stamps simulated time and DDS carries no source timestamp: no latency, not a "
                            + "made-up one: " + ros2);
            assertTrue(robot.commands() > 0, "the simulator obeyed");
        }
    }

    /**
     * Bridge to bridge: the simulator over DDS and the controller over DDS on one domain, no other
     * node. Each bridge sees the other's readers and writers as a ROS 2 node's (the plugin
     * announces its own entities on ros_discovery_info), so the routes come up on both sides.
     */
    @Test
    @Requires(DdsBridgeBuilt.class)
    void runRos2DdsDrivesTheSimulatorServedOverDdsOnTheSameDomain() throws Exception {
        Path out = dir.resolve("bridges");
        try (PlayerSimServer server = simulator(shortLeg(), 10);
             Ros2SimRobot robot = Ros2SimRobot.start(server, ddsContext(46), "/", line -> { })) {
            int status = quietly("run", "--ros2", "--dds", "--domain", "46", "--scenario", shortLeg(), "--time-scale",
                    "10", "--out", out.toString(), "--quiet");
            assertEquals(0, status, "run --ros2 --dds exit status");
            JsonNode report = JSON.readTree(out.resolve("report.json").toFile());
            assertEquals("completed", report.path("run").path("outcome").asText(), "run: " + report.path("run"));
            assertTrue(report.path("ros2").path("scans").asLong() > 0, "ros2: " + report.path("ros2"));
            assertTrue(robot.commands() > 0, "the simulator obeyed the controller over DDS");
        }
    }

    @Test
    @Requires(DdsBridgeBuilt.class)
    void aCycloneDdsRobotSendingNanPosesIsHaltedWithZeroVelocityAndTheRunEndsAsAnError() throws Exception {
        Path script = peerScript();
        Path out = dir.resolve("nan");
        try (PlayerSimServer server = simulator(shortLeg(), 1);
             Ros2SimRobot robot = Ros2SimRobot.start(server, ddsContext(44), "/", line -> { })) {
            Process relay = peer(script, "relay", "--from", "44", "--to", "45", "--restamp", "--nan-odom-after", "4");
            JsonNode relayed;
            Captured run;
            try (BufferedReader relayOut = new BufferedReader(new InputStreamReader(relay.getInputStream(),
                    StandardCharsets.UTF_8))) {
                assertEquals("ready", relayOut.readLine(), "the Cyclone DDS robot started");
                run = withStderr("run", "--ros2", "--dds", "--domain", "45", "--scenario", shortLeg(), "--time-scale",
                        "1", "--out", out.toString(), "--quiet");
                Thread.sleep(1000); // the last zero Twist crosses the bridge and DDS before the robot is asked
                relay.getOutputStream().close();
                relayed = JSON.readTree(relayOut.readLine());
            } finally {
                if (!relay.waitFor(20, TimeUnit.SECONDS)) {
                    relay.destroyForcibly();
                }
            }
            String err = run.err();
            assertEquals(1, run.status(), "stderr: " + err);
            assertTrue(relayed.path("nan_odometry").asLong() > 0, "NaN poses were sent: " + relayed);
            assertEquals("[0.0,0.0]", relayed.path("last_command").toString(), "halted with a zero Twist: " + relayed);
            assertEquals(1, err.lines().filter(l -> l.contains("ROS 2 topic /odom sent only impossible samples")).count(),
                    "one line names the topic: " + err);
            JsonNode ros2 = JSON.readTree(out.resolve("report.json").toFile()).path("ros2");
            assertTrue(ros2.path("fault").asText().contains("x = NaN"), "ros2: " + ros2);
            assertEquals(Ros2DataTask.LATENCY_FROM_HEADER, ros2.path("scan_latency_from").asText(),
                    "re-stamped scans give the latency from their header stamps: " + ros2);
            assertTrue(robot.commands() > 0, "the simulator was driven before the halt");
        }
    }

    /**
     * Issue 38: a robot whose {@code rt/scan} carries another type than LaserScan. DDS matches no
     * reader to a writer of another type (or the bridge routes the type it saw first, whose samples
     * do not decode); either way the run says so in one line while it goes on, a warning on
     * stderr, and as a notice in the report.
     */
    @Test
    @Requires(DdsBridgeBuilt.class)
    void aRobotPublishingItsScanAsAnotherTypeIsToldInOneLine() throws Exception {
        Path script = peerScript();
        Path out = dir.resolve("wrong-type");
        Process robot = peer(script, "twist-on", "--domain", "53", "--topic", "scan");
        String err;
        try (BufferedReader robotOut = new BufferedReader(new InputStreamReader(robot.getInputStream(),
                StandardCharsets.UTF_8))) {
            assertEquals("ready", robotOut.readLine(), "the Cyclone DDS robot started");
            err = withStderr("run", "--ros2", "--dds", "--domain", "53", "--scenario", shortLeg(), "--time-scale", "1",
                    "--out", out.toString(), "--quiet").err();
        } finally {
            robot.getOutputStream().close();
            if (!robot.waitFor(20, TimeUnit.SECONDS)) {
                robot.destroyForcibly();
            }
        }
        String told = "rt/scan is published as geometry_msgs/msg/Twist, rtaware expects sensor_msgs/msg/LaserScan: "
                + "none of its samples can be read";
        assertEquals(1, err.lines().filter(l -> l.equals("ros2: " + told)).count(), "one warning while it ran: " + err);
        JsonNode ros2 = JSON.readTree(out.resolve("report.json").toFile()).path("ros2");
        assertTrue(ros2.path("notices").toString().contains(told), "the report's notices: " + ros2);
        assertEquals(0, ros2.path("scans").asLong(), "no scan: " + ros2);
    }

    /**
     * Runs {@code bench --tasks 2 --export --dds} on domain 0 for 12 s and the Cyclone DDS node in
     * {@code mode} beside it for 9 s.
     *
     * @return what the node saw, once it and the bench ended well
     */
    private JsonNode besideBenchExportDds(String mode) throws Exception {
        Path script = peerScript();
        assumeTrue(System.getenv("ROS_DOMAIN_ID") == null, "bench exports on ROS_DOMAIN_ID, set here");
        AtomicInteger status = new AtomicInteger(-1);
        Thread bench = new Thread(() -> status.set(quietly("bench", "--tasks", "2", "--period", "10ms", "--duration",
                "12s", "--export", "--dds", "--quiet")), "bench --export --dds");
        bench.start();
        JsonNode seen;
        try {
            Process node = peer(script, mode, "--domain", "0", "--seconds", "9");
            String output = new String(node.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertTrue(node.waitFor(60, TimeUnit.SECONDS), "the Cyclone DDS node finished");
            seen = lastJsonLine(output);
            assertEquals(0, node.exitValue(), "the node's checks: " + seen);
        } finally {
            bench.join(60_000);
        }
        assertEquals(0, status.get(), "bench --export --dds exit status");
        return seen;
    }

    @Test
    @Requires(DdsBridgeBuilt.class)
    void aCycloneDdsNodeReadsTheExportedDiagnosticsOverDds() throws Exception {
        JsonNode seen = besideBenchExportDds("diagnostics");
        assertTrue(seen.path("messages").asInt() >= 3, "one DiagnosticArray a second: " + seen);
        assertTrue(seen.path("names").toString().contains("rtaware: task t1"), "the tasks' health: " + seen);
    }

    /** Issue 37: ROS 2's topic statistics of every task and key, read by a stock DDS node. */
    @Test
    @Requires(DdsBridgeBuilt.class)
    void aCycloneDdsNodeReadsTheExportedTopicStatisticsOfEveryTaskAndKeyOverDds() throws Exception {
        Ros2PythonPeer.assertStatisticsOfEveryTaskAndKey(besideBenchExportDds("statistics"));
    }

    /**
     * Nothing DDS opens listens beyond the chosen interface (issue 38): with a DDS context on
     * {@code lo}, every UDP socket of this JVM and of the processes it started is bound to
     * 127.0.0.1, none to 0.0.0.0 or ::, and there are some (Cyclone DDS's). Read from
     * {@code /proc/net/udp} and {@code /proc/net/udp6}, matched to the processes' socket inodes.
     */
    @Test
    @Requires(DdsBridgeBuilt.class)
    void aDdsContextOnLoopbackBindsEveryUdpSocketTo127001() throws Exception {
        assumeTrue(Files.isReadable(Path.of("/proc/net/udp")), "skipped: no /proc/net/udp (Linux only)");
        try (Ros2Context ignored = ddsContext(47)) {
            List<ProcessHandle> processes = new ArrayList<>(List.of(ProcessHandle.current()));
            processes.addAll(ProcessHandle.current().descendants().toList());
            List<String> bound = UdpSockets.localAddresses(processes);
            assertFalse(bound.isEmpty(), "Cyclone DDS's UDP sockets were found among " + processes);
            assertEquals(List.of(), bound.stream().filter(a -> !a.startsWith("127.0.0.1:")).toList(),
                    "UDP sockets bound beyond loopback; all: " + bound);
        }
    }

    @Test
    void badDdsSettingsAreOneLineAndExitStatusTwo() throws Exception {
        assertEquals(2, quietly("run", "--ros2", "--dds", "--domain", "300", "--quiet"));
        assertEquals(2, quietly("run", "--dds", "--quiet"), "--dds without --ros2 or --export");
        assertEquals(2, quietly("run", "--ros2", "--dds-interface", "eth0", "--quiet"), "--dds-interface without --dds");
        assertEquals(2, quietly("run", "--ros2", "--dds", "--zenoh", "tcp/127.0.0.1:7447", "--quiet"));
        assertEquals(2, quietly("sim", "--ros2", "--dds", "--listen", "tcp/127.0.0.1:0"));
        String missing = dir.resolve("missing.xml").toString();
        assertEquals(List.of("rtaware: --dds: CYCLONEDDS_URI: cannot read 'file://" + missing + "'"),
                cliLines(Map.of("CYCLONEDDS_URI", "file://" + missing), "run", "--ros2", "--dds", "--quiet"),
                "one line naming the value");
        assertEquals(List.of("rtaware: --dds-interface: no network interface named 'rtaware9' on this machine"),
                cliLines(Map.of(), "run", "--ros2", "--dds", "--dds-interface", "rtaware9", "--quiet"),
                "an interface this machine lacks is named before anything starts (it was a 7-line Rust panic after 11 s)");
    }

    /**
     * A configuration Cyclone DDS refuses ends the bridge as it starts, and the command in one
     * line with Cyclone's own reason, exit status 2 (it was a 7-line Rust panic after the 10 s
     * start timeout): the reason can come only from the bridge's refusal, not from a timeout.
     */
    @Test
    @Requires(DdsBridgeBuilt.class)
    void aCycloneConfigurationCycloneDdsRefusesIsOneLineWithItsReason() throws Exception {
        String uri = "<CycloneDDS><Domain><General><Interfaces><NetworkInterface name=\"rtaware9\"/></Interfaces>"
                + "</General></Domain></CycloneDDS>";
        assertEquals(List.of("rtaware: --dds: cannot join DDS domain 0 (configured by CYCLONEDDS_URI) through "
                        + "zenoh-plugin-ros2dds: the ROS 2 DDS bridge did not start: Cyclone DDS refused domain 0: rtaware9: "
                        + "does not match an available interface."),
                cliLines(Map.of("CYCLONEDDS_URI", uri), "run", "--ros2", "--dds", "--domain", "0", "--quiet"));
    }

    /**
     * Runs the command line in a JVM of its own (so that everything its processes print is seen)
     * and checks it exits with status 2.
     *
     * @return its output's lines but Maven's and the JVM's own ({@code [...]})
     */
    private List<String> cliLines(Map<String, String> environment, String... args) throws Exception {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path"), RtawareCli.class.getName()));
        command.addAll(List.of(args));
        command.addAll(List.of("--out", dir.resolve("cli-" + System.nanoTime()).toString()));
        ProcessBuilder cli = new ProcessBuilder(command).redirectErrorStream(true);
        cli.environment().remove("CYCLONEDDS_URI");
        cli.environment().putAll(environment);
        Process p = cli.start();
        String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        assertEquals(2, p.exitValue(), output);
        return output.lines().filter(l -> !l.startsWith("[")).toList();
    }

    /**
     * A command's exit status and standard error.
     *
     * @param status the exit status
     * @param err what it wrote on standard error
     */
    private record Captured(int status, String err) {
    }

    /** Runs a command as {@link #quietly} does, keeping its standard error. */
    private static Captured withStderr(String... args) {
        ByteArrayOutputStream stderr = new ByteArrayOutputStream();
        PrintStream saved = System.err;
        int status;
        try {
            System.setErr(new PrintStream(stderr, true, StandardCharsets.UTF_8));
            status = quietly(args);
        } finally {
            System.setErr(saved);
        }
        return new Captured(status, stderr.toString(StandardCharsets.UTF_8));
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
}
