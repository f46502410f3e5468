package io.rtaware.app.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import io.rtaware.app.RtawareCli;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Objects;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The whole path of the paper, on real threads: controller <-> TCP <-> the built-in simulator's
 * Player server, on a shortened course at a high time scale. Checks the outcome and the report
 * folder, not timing.
 */
class RunEndToEndTest {

    @TempDir
    Path dir;

    @Test
    void shortCourseCompletesAndWritesTheReportFolder() throws Exception {
        Path scenario = Path.of(Objects.requireNonNull(getClass().getResource("/scenarios/short-leg.yaml")).toURI());
        Path out = dir.resolve("run");
        PrintStream saved = System.out;
        ByteArrayOutputStream stdout = new ByteArrayOutputStream();
        int status;
        try {
            System.setOut(new PrintStream(stdout, true, StandardCharsets.UTF_8));
            status = RtawareCli.execute("run", "--scenario", scenario.toString(), "--time-scale", "10",
                    "--out", out.toString(), "--quiet", "--seed", "7");
        } finally {
            System.setOut(saved);
        }
        String printed = stdout.toString(StandardCharsets.UTF_8);
        assertEquals(0, status, "exit status of a finished run; output:\n" + printed);
        assertTrue(printed.contains("rtaware summary"), "the summary table is printed");

        JsonNode report = new ObjectMapper().readTree(out.resolve("report.json").toFile());
        assertEquals("rtaware.report/1", report.path("schema").asText());
        JsonNode run = report.path("run");
        assertEquals("completed", run.path("outcome").asText(), "outcome; run section: " + run);
        assertTrue(run.path("completed").asBoolean());
        assertEquals(1, run.path("waypoints_reached").asInt());
        assertEquals(0, run.path("collisions").asInt(), "no collisions");
        assertEquals("ground_truth", run.path("measured_on").asText(), "the simulator offers simulation:0");
        assertEquals("koala", run.path("robot_model").path("name").asText(), "the Koala by default: " + run);
        assertEquals(0.1, run.path("robot_model").path("top_speed_mps").asDouble());
        assertEquals(30.0, run.path("robot_model").path("command_latency_ms").asDouble());
        assertTrue(run.path("completed_means").asText().contains("own estimate"), run.toString());
        JsonNode pass = run.path("waypoint_passes").path(0);
        assertEquals(0, pass.path("index").asInt(), "the finish was believed passed: " + run);
        assertTrue(pass.path("believed_distance_m").asDouble() <= 0.3 + 1e-9, "by odometry within tolerance: " + run);
        assertTrue(pass.path("true_distance_m").asDouble() >= 0, "and measured in truth: " + run);
        String ending = String.format(java.util.Locale.ROOT, "completed (finish reached by odometry; %.2f m from it in truth)",
                pass.path("true_distance_m").asDouble());
        assertTrue(printed.contains("run: " + ending), "the terminal says the finish is odometry's and how far the"
                + " truth was: " + ending + " in\n" + printed);
        assertTrue(Files.readString(out.resolve("report.md")).contains("run: " + ending), "and report.md");
        assertTrue(run.path("distance_to_finish_m").asDouble() < 1.0, "near the finish in truth: " + run);
        assertTrue(run.path("mediator").has("obstacle") && run.path("mediator").has("waypoint"), run.toString());
        assertTrue(run.path("distance_travelled_m").asDouble() > 1.2, "the robot drove the leg (odometry may stop it short): " + run);
        assertEquals(100.0, run.path("periods_ms").path("waypoint").asDouble());
        for (String task : new String[] {"player", "waypoint", "obstacle", "occupancy", "planner", "mediator"}) {
            boolean found = false;
            for (JsonNode t : report.path("tasks")) {
                found |= t.path("name").asText().equals(task) && t.path("runs").asLong() > 0;
            }
            assertTrue(found, "task " + task + " ran and is reported");
        }
        for (String file : new String[] {"report.md", "trajectory.csv", "trajectory.png", "map.pgm", "map.yaml"}) {
            assertTrue(Files.size(out.resolve(file)) > 0, file + " written");
        }
        assertTrue(Files.readString(out.resolve("trajectory.csv")).startsWith("t_s,x_m,y_m,yaw_rad,odom_x_m,odom_y_m,odom_yaw_rad\n"));
    }

    @Test
    void unreachablePlayerServerIsAOneLineUserError() {
        assertEquals(2, RtawareCli.execute("run", "--player", "127.0.0.1:1", "--out", dir.resolve("x").toString(),
                "--quiet"));
    }

    @Test
    void badRobotOrTopSpeedIsAOneLineUserError() {
        assertEquals(2, RtawareCli.execute("run", "--robot", "pioneer", "--out", dir.resolve("x").toString(), "--quiet"));
        assertEquals(2, RtawareCli.execute("run", "--top-speed", "0.7", "--out", dir.resolve("x").toString(), "--quiet"));
        assertEquals(2, RtawareCli.execute("run", "--top-speed", "0", "--out", dir.resolve("x").toString(), "--quiet"));
        assertEquals(2, RtawareCli.execute("run", "--inflation-margin", "-0.1", "--out", dir.resolve("x").toString(),
                "--quiet"));
    }

    @Test
    void missingScenarioFileIsAOneLineUserError() {
        assertEquals(2, RtawareCli.execute("run", "--scenario", dir.resolve("nope.yaml").toString(), "--quiet"));
    }
}
