package io.rtaware.sim.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.robot.geometry.Point2d;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ScenarioLoaderTest {

    @TempDir
    Path dir;

    private static final String GOOD = "start: {x: 1.0, y: 2.0, yaw: 0.5}\n"
            + "waypoints:\n  - {x: 3, y: 4}\n  - {x: 5, y: 6}\n"
            + "goal_tolerance_m: 0.25\ntime_limit_s: 60\nextra_field: ignored\n";

    @Test
    void loadsFileWithoutMap() throws IOException {
        Path f = dir.resolve("course.yaml");
        Files.writeString(f, GOOD);
        Scenario s = ScenarioLoader.load(f.toString());
        assertEquals("course", s.name());
        assertTrue(s.map().isEmpty());
        assertEquals(0.5, s.start().yawRad());
        assertEquals(new Point2d(5, 6), s.finish());
        assertEquals(0.25, s.goalToleranceM());
        assertEquals(60.0, s.timeLimitS());
    }

    @Test
    void loadsMapRelativeToTheFile() throws IOException {
        Files.writeString(dir.resolve("m.pgm"), "P2\n2 2\n255\n0 255\n255 255\n");
        Files.writeString(dir.resolve("m.yaml"), "image: m.pgm\nresolution: 1\norigin: [0, 0, 0]\n"
                + "occupied_thresh: 0.65\nfree_thresh: 0.196\nnegate: 0\n");
        Path f = dir.resolve("withmap.yaml");
        Files.writeString(f, "map: m.yaml\n" + GOOD);
        Scenario s = ScenarioLoader.load(f);
        assertTrue(s.map().orElseThrow().isObstacleAt(0.5, 1.5));
    }

    private String error(String text) throws IOException {
        Path f = dir.resolve("bad.yaml");
        Files.writeString(f, text);
        ScenarioException e = assertThrows(ScenarioException.class, () -> ScenarioLoader.load(f));
        assertFalse(e.getMessage().contains("\n"), e.getMessage());
        assertTrue(e.getMessage().contains("bad.yaml"), e.getMessage());
        return e.getMessage();
    }

    @Test
    void malformedFilesNameFileFieldAndValue() throws IOException {
        String m = error(GOOD.replace("goal_tolerance_m: 0.25", "goal_tolerance_m: -1"));
        assertTrue(m.contains("'goal_tolerance_m'") && m.contains("-1"), m);
        m = error(GOOD.replace("time_limit_s: 60", "time_limit_s: soon"));
        assertTrue(m.contains("'time_limit_s'") && m.contains("soon"), m);
        m = error(GOOD.replace("{x: 5, y: 6}", "{x: 5, y: north}"));
        assertTrue(m.contains("'waypoints[1].y'") && m.contains("north"), m);
        m = error(GOOD.replace("x: 1.0,", ""));
        assertTrue(m.contains("'start.x'") && m.contains("missing"), m);
        m = error("map: nowhere.yaml\n" + GOOD);
        assertTrue(m.contains("'map'") && m.contains("nowhere.yaml"), m);
        m = error("start: [\n");
        assertTrue(m.contains("YAML"), m);
        m = error(GOOD.replace("waypoints:\n  - {x: 3, y: 4}\n  - {x: 5, y: 6}\n", "waypoints: []\n"));
        assertTrue(m.contains("'waypoints'") && m.contains("[]"), m);
    }

    @Test
    void robotSectionChoosesTheModelAndOverridesItsParameters() throws IOException {
        Path f = dir.resolve("robot.yaml");
        Files.writeString(f, GOOD + "robot: {model: koala, top_speed_mps: 0.3, command_latency_ms: 50,"
                + " odometry_rotation_scale_error: 0.1}\n");
        io.rtaware.sim.world.RobotModel m = ScenarioLoader.load(f).robot().orElseThrow();
        assertEquals("koala", m.name());
        assertEquals(0.3, m.topSpeedMps());
        assertEquals(50_000_000L, m.commandLatencyNs());
        assertEquals(0.1, m.odometry().rotationScaleError());
        assertEquals(io.rtaware.sim.world.OdometryError.KOALA.distanceScaleError(), m.odometry().distanceScaleError());
        Files.writeString(f, GOOD + "robot: {model: ideal}\n");
        assertTrue(ScenarioLoader.load(f).robot().orElseThrow().isIdeal());
        Files.writeString(f, GOOD);
        assertTrue(ScenarioLoader.load(f).robot().isEmpty(), "no section: the command's default");
        String e = error(GOOD + "robot: {model: pioneer}\n");
        assertTrue(e.contains("'robot.model'") && e.contains("pioneer"), e);
        e = error(GOOD + "robot: {model: koala, wheels: 4}\n");
        assertTrue(e.contains("'robot.wheels'") && e.contains("unknown robot parameter"), e);
        e = error(GOOD + "robot: {top_speed_mps: 2}\n");
        assertTrue(e.contains("'robot.top_speed_mps'") && e.contains("2.0"), e);
    }

    @Test
    void missingFileAndUnknownBuiltIn() {
        ScenarioException e = assertThrows(ScenarioException.class, () -> ScenarioLoader.load("no/such.yaml"));
        assertTrue(e.getMessage().contains("no/such.yaml"));
        assertThrows(ScenarioException.class, () -> ScenarioLoader.builtIn("moon"));
    }

    /** Issue 34: 'ofice' was "ofice: file not found", naming none of the built-in scenarios. */
    @Test
    void aMistypedBuiltInNameSuggestsTheNearestAndListsThemAll() {
        assertEquals("unknown scenario 'ofice'; did you mean 'office'? (built-in scenarios: paper-room, corridor, office;"
                + " or give a scenario YAML file)",
                assertThrows(ScenarioException.class, () -> ScenarioLoader.load("ofice")).getMessage());
        assertEquals("unknown scenario 'warehouse' (built-in scenarios: paper-room, corridor, office; or give a scenario"
                + " YAML file)", assertThrows(ScenarioException.class, () -> ScenarioLoader.load("warehouse")).getMessage());
        assertTrue(assertThrows(ScenarioException.class, () -> ScenarioLoader.load("course.yaml")).getMessage()
                .endsWith("course.yaml: file not found"), "a file name is reported as a missing file");
    }
}
