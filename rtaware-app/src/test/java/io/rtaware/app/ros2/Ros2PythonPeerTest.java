package io.rtaware.app.ros2;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import io.rtaware.app.RtawareCli;
import io.rtaware.core.testing.PythonPeers;
import io.rtaware.core.testing.Requires;
import io.rtaware.core.time.SystemClock;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.ros2.graph.Ros2Context;
import io.rtaware.sim.ros2.Ros2SimRobot;
import io.rtaware.sim.scenario.ScenarioLoader;
import io.rtaware.sim.server.PlayerSimServer;
import io.rtaware.sim.server.ServerConfig;
import io.rtaware.sim.server.SimCommandSupport;
import io.rtaware.zenoh.NativeZenohLayer;
import io.rtaware.zenoh.ZenohConfig;
import io.rtaware.zenoh.ZenohException;
import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * The simulator as a ROS 2 robot against an independent implementation of the same conventions:
 * a Python Zenoh router standing in for rmw_zenohd, and a Python peer built on zenoh-ros2-sdk and
 * rosbags ({@code src/test/resources/ros2/ros2_peer.py}) that decodes /scan and /odom, checks the
 * REP 105 frames on /tf and /tf_static, lists the graph through liveliness tokens and drives the
 * robot on /cmd_vel, and reads the topic statistics {@code bench --export} publishes on
 * /statistics. The Python interpreter of a
 * virtual environment with those packages is named by {@code RTAWARE_PEER_PYTHON} (.ci/run makes
 * one); without it, or without the native Zenoh layer, the test is skipped, except under CI=true
 * where it fails.
 */
@Timeout(180)
@Requires({NativeZenohLayer.class, PythonPeers.class})
class Ros2PythonPeerTest {

    @TempDir
    Path dir;

    /** What a test does while the Python router runs on {@code endpoint}. */
    private interface WithRouter {
        void run(String python, Path script, String endpoint) throws Exception;
    }

    /** Starts the Python router on a free loopback endpoint, runs {@code test}, stops the router. */
    private void withRouter(WithRouter test) throws Exception {
        String python = PythonPeers.python();
        Path script = Ros2PythonPeer.script(dir);
        String endpoint = Ros2Wiring.freeLoopbackEndpoint();
        Process router = new ProcessBuilder(python, script.toString(), "router", "--listen", endpoint)
                .redirectError(ProcessBuilder.Redirect.INHERIT).start();
        try (BufferedReader routerOut = new BufferedReader(
                new InputStreamReader(router.getInputStream(), StandardCharsets.UTF_8))) {
            assertEquals("ready", routerOut.readLine(), "the Python router started");
            test.run(python, script, endpoint);
        } finally {
            router.getOutputStream().close();
            if (!router.waitFor(10, TimeUnit.SECONDS)) {
                router.destroyForcibly();
            }
        }
    }

    /** Runs the peer to its end; its last line, a JSON object, after checking it exited 0. */
    private static JsonNode peerResult(Process peer) throws Exception {
        String output = new String(peer.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
        assertTrue(peer.waitFor(90, TimeUnit.SECONDS), "the Python peer finished");
        JsonNode seen = new ObjectMapper().readTree(output.lines().reduce((a, b) -> b).orElse("{}"));
        assertEquals(0, peer.exitValue(), "the Python peer's checks: " + seen.path("failures"));
        return seen;
    }

    @Test
    void aPythonRos2PeerSeesTheSimulatorAndDrivesIt() throws Exception {
        withRouter((python, script, endpoint) -> {
            try (PlayerSimServer server = SimCommandSupport.start(ScenarioLoader.load("paper-room"), new SystemClock(),
                         ServerConfig.defaults(0), 1, 4);
                 Ros2SimRobot robot = Ros2SimRobot.start(server, openThrough(endpoint), "/", line -> { })) {
                Pose2d start = server.groundTruth();
                JsonNode seen = peerResult(new ProcessBuilder(python, script.toString(), "check", "--router", endpoint,
                        "--timeout", "60").redirectError(ProcessBuilder.Redirect.INHERIT).start());
                assertTrue(seen.path("first_scan").path("beams").asInt() > 100, "LaserScan decoded: " + seen);
                assertEquals("odom", seen.path("first_odometry").path("frame").asText(), "Odometry decoded: " + seen);
                assertEquals("base_link", seen.path("first_odometry").path("child").asText(), "odometry's child frame");
                assertEquals("laser", seen.path("first_scan").path("frame").asText(), "the scan's frame");
                assertEquals("[[\"odom\",\"base_link\"]]", seen.path("tf").toString(), "/tf as the peer decoded it");
                assertEquals("[[\"base_link\",\"laser\"]]", seen.path("tf_static").toString(),
                        "/tf_static as the peer decoded it");
                assertTrue(seen.path("tf_matched_odometry").asInt() > 0, "/tf stamped as odometry samples: " + seen);
                assertTrue(seen.path("scan_stamps_ns").size() > 0, "scan stamps: " + seen);
                assertTrue(seen.path("clocks").asInt() >= 3, "/clock in the world's time: " + seen);
                for (JsonNode stamp : seen.path("scan_stamps_ns")) {
                    assertEquals(0, stamp.asLong() % 100_000_000L, "a scan stamped at its first beam, the start of "
                            + "the URG-04LX's sweep on its 100 ms turn grid (its delivery is 77 ms later): " + stamp);
                }
                assertEquals("rtaware_sim", seen.path("scan_publishers").path(0).path("node").asText());
                assertTrue(robot.commands() > 0, "the simulator obeyed the Python /cmd_vel");
                Pose2d end = server.groundTruth();
                assertTrue(Math.hypot(end.xM() - start.xM(), end.yM() - start.yM()) > 0.1,
                        "ground truth moved from " + start + " to " + end);
            }
        });
    }

    /** Issue 37: {@code --export} publishes ROS 2's topic statistics, read by zenoh-ros2-sdk through the router. */
    @Test
    void aPythonRos2PeerReadsTheTopicStatisticsOfEveryTaskAndKey() throws Exception {
        withRouter((python, script, endpoint) -> {
            CompletableFuture<Integer> bench = CompletableFuture.supplyAsync(() -> RtawareCli.execute("bench", "--tasks",
                    "2", "--period", "10ms", "--work", "0", "--duration", "10s", "--quiet", "--export",
                    "--export-zenoh", endpoint));
            JsonNode seen = peerResult(new ProcessBuilder(python, script.toString(), "statistics", "--router", endpoint,
                    "--seconds", "7").redirectError(ProcessBuilder.Redirect.INHERIT).start());
            assertEquals(0, bench.get(60, TimeUnit.SECONDS), "bench --export");
            Ros2PythonPeer.assertStatisticsOfEveryTaskAndKey(seen);
        });
    }

    private static Ros2Context openThrough(String router) throws ZenohException {
        return Ros2Context.open(ZenohConfig.loopbackPeer().withConnect(List.of(router)), 0);
    }
}
