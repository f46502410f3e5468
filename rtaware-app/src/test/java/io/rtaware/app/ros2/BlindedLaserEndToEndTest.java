package io.rtaware.app.ros2;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import io.rtaware.app.RtawareCli;
import io.rtaware.core.testing.Requires;
import io.rtaware.zenoh.NativeZenohLayer;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Objects;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 24, finding 1, end to end over ROS 2: a laser that reports {@code -Inf} on every beam
 * ("closer than the minimum range", REP 117) is an obstacle the controller never drives into,
 * and a laser that sends scans of no beams (stamped 100 s ahead, as the hostile peer did) is
 * impossible data that halts the robot. Outcomes and reports, not timing.
 */
@Timeout(120)
class BlindedLaserEndToEndTest {

    @TempDir
    Path dir;

    private static String freeEndpoint() throws Exception {
        try (ServerSocket s = new ServerSocket(0)) {
            return "tcp/127.0.0.1:" + s.getLocalPort();
        }
    }

    private String shortLeg() throws Exception {
        return Path.of(Objects.requireNonNull(getClass().getResource("/scenarios/short-leg.yaml")).toURI()).toString();
    }

    private record Outcome(int status, String stderr, JsonNode report) {
    }

    private Outcome run(ScriptedRos2Robot robot, String endpoint, Path out) throws Exception {
        PrintStream savedOut = System.out;
        PrintStream savedErr = System.err;
        ByteArrayOutputStream stderr = new ByteArrayOutputStream();
        int status;
        try (robot) {
            System.setOut(new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8));
            System.setErr(new PrintStream(stderr, true, StandardCharsets.UTF_8));
            status = RtawareCli.execute("run", "--ros2", "--zenoh", endpoint, "--scenario", shortLeg(), "--time-scale",
                    "1", "--stuck-after", "3s", "--out", out.toString(), "--quiet");
        } finally {
            System.setOut(savedOut);
            System.setErr(savedErr);
        }
        assertNull(robot.failure(), "the test robot ran");
        return new Outcome(status, stderr.toString(StandardCharsets.UTF_8),
                new ObjectMapper().readTree(out.resolve("report.json").toFile()));
    }

    @Test
    @Requires(NativeZenohLayer.class)
    void aLaserSeeingEverythingCloserThanItsMinimumRangeIsNeverDrivenInto() throws Exception {
        String endpoint = freeEndpoint();
        ScriptedRos2Robot robot = ScriptedRos2Robot.scanning(endpoint, 181, Float.NEGATIVE_INFINITY, 0);
        Outcome o = run(robot, endpoint, dir.resolve("minus-inf"));
        JsonNode run = o.report().path("run");
        assertEquals(0, o.status(), "a stuck run is a finished run; stderr: " + o.stderr());
        assertEquals("stuck", run.path("outcome").asText(), "run section: " + run);
        assertEquals(0f, robot.maxForwardMps(), "never commanded forward: every beam is an obstacle at 0.02 m");
        assertTrue(robot.distanceFromStartM() < 1e-9, "it turned in place: " + robot.distanceFromStartM() + " m");
        JsonNode ros2 = o.report().path("ros2");
        assertTrue(ros2.path("scans").asLong() > 0, "the scans were accepted as data, not rejected: " + ros2);
        assertEquals(0, ros2.path("rejected_samples").path("/scan").asLong(), "ros2: " + ros2);
        assertEquals(0, ros2.path("dropped_beams").asLong(), "-Inf is a reading, not a dropped beam: " + ros2);
    }

    @Test
    @Requires(NativeZenohLayer.class)
    void scansOfNoBeamsAreImpossibleDataAndHaltTheRobot() throws Exception {
        String endpoint = freeEndpoint();
        ScriptedRos2Robot robot = ScriptedRos2Robot.scanning(endpoint, 0, 4f, 100_000_000_000L);
        Outcome o = run(robot, endpoint, dir.resolve("empty"));
        assertEquals(1, o.status(), "stderr: " + o.stderr());
        JsonNode run = o.report().path("run");
        assertEquals("error", run.path("outcome").asText(), "run section: " + run);
        assertTrue(run.path("reason").asText().startsWith("ROS 2 topic /scan sent only impossible samples"),
                run.path("reason").asText());
        assertTrue(run.path("reason").asText().contains("the scan has no beams"), run.path("reason").asText());
        JsonNode ros2 = o.report().path("ros2");
        assertEquals(0, ros2.path("scans").asLong(), "no scan was committed: " + ros2);
        assertTrue(ros2.path("rejected_samples").path("/scan").asLong() > 0, "ros2: " + ros2);
        assertTrue(robot.lastTwist() != null && robot.lastTwist().isStop(), "the last command stops the robot");
        assertTrue(robot.distanceFromStartM() < 0.2,
                "halted within a second of world time, not driven blind: " + robot.distanceFromStartM() + " m");
    }
}
