package io.rtaware.app.ros2;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import io.rtaware.app.RtawareCli;
import io.rtaware.zenoh.ZenohLibrary;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
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
class Ros2RunEndToEndTest {

    @TempDir
    Path dir;

    private static void requireNativeZenoh() {
        String reason = ZenohLibrary.unavailableReason();
        if (reason != null && "true".equals(System.getenv("CI")) && !"1".equals(System.getenv("RTAWARE_NO_RUST"))) {
            fail("CI=true but " + reason + " (.ci/run sets RTAWARE_NO_RUST=1 when the machine has no Rust toolchain)");
        }
        assumeTrue(reason == null, () -> "skipped: " + reason);
    }

    private Path shortLeg() throws Exception {
        return Path.of(Objects.requireNonNull(getClass().getResource("/scenarios/short-leg.yaml")).toURI());
    }

    private static JsonNode completedReport(Path out, String measuredOn) throws Exception {
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
    void runRos2DrivesTheBuiltInSimulatorAsARos2Robot() throws Exception {
        requireNativeZenoh();
        Path out = dir.resolve("run");
        int status = quietly("run", "--ros2", "--scenario", shortLeg().toString(), "--time-scale", "10",
                "--out", out.toString(), "--quiet", "--seed", "7");
        assertEquals(0, status);
        completedReport(out, "ground_truth");
    }

    @Test
    void runRos2DrivesASimulatorServingRos2InAnotherSession() throws Exception {
        requireNativeZenoh();
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
            int status = -1;
            // The simulator binds its endpoint asynchronously: an unreachable router is exit 2, retry.
            for (int attempt = 0; attempt < 50 && status != 0; attempt++) {
                status = quietly("run", "--ros2", "--zenoh", endpoint, "--namespace", "/robot1", "--scenario",
                        shortLegUnchecked(), "--time-scale", "10", "--out", out.toString(), "--quiet");
                assertTrue(status == 0 || status == 2, "exit status " + status);
                assertTrue(sim.isAlive(), "the simulator is serving (its exit status: " + simStatus.get() + ")");
            }
            assertEquals(0, status);
            completedReport(out, "odometry");
        } finally {
            sim.interrupt();
            sim.join(10_000);
        }
    }

    private String shortLegUnchecked() {
        try {
            return shortLeg().toString();
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }

    @Test
    void unreachableRouterIsOneLineAndExitTwo() throws Exception {
        requireNativeZenoh();
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
