package io.rtaware.sim.scenario;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.robot.geometry.Point2d;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.sim.map.OccupancyMap;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.api.Test;

class PaperRoomTest {

    private static byte[] resource(String name) throws IOException {
        try (InputStream in = PaperRoomTest.class.getResourceAsStream("/io/rtaware/sim/scenario/" + name)) {
            return in.readAllBytes();
        }
    }

    @Test
    void shippedResourcesAreWhatTheGeneratorProduces() throws IOException {
        assertArrayEquals(PaperRoomGenerator.pgm(), resource("paper-room.pgm"));
        assertEquals(PaperRoomGenerator.mapYaml(), new String(resource("paper-room.yaml"), StandardCharsets.UTF_8));
        assertEquals(PaperRoomGenerator.scenarioYaml(),
                new String(resource("paper-room.scenario.yaml"), StandardCharsets.UTF_8));
    }

    @Test
    void builtInScenarioHasTheIssueGeometry() {
        Scenario s = ScenarioLoader.load("paper-room");
        assertEquals("paper-room", s.name());
        assertEquals(new Pose2d(0.8, 0.8, 0.0), s.start());
        assertEquals(List.of(new Point2d(8.8, 0.8), new Point2d(8.8, 5.4), new Point2d(0.8, 5.4),
                new Point2d(0.8, 2.6)), s.waypoints());
        assertEquals(new Point2d(0.8, 2.6), s.finish());
        assertEquals(0.3, s.goalToleranceM());
        assertEquals(360.0, s.timeLimitS());
        OccupancyMap m = s.map().orElseThrow();
        assertEquals(0.02, m.resolutionM());
        assertEquals(500, m.widthCells());
        assertEquals(330, m.heightCells());
        // room interior free just inside every wall, walls just outside
        assertFalse(m.isObstacleAt(0.01, 0.01));
        assertFalse(m.isObstacleAt(9.59, 6.19));
        assertTrue(m.isObstacleAt(-0.01, 3.0));
        assertTrue(m.isObstacleAt(9.61, 3.0));
        assertTrue(m.isObstacleAt(4.0, -0.01));
        assertTrue(m.isObstacleAt(4.0, 6.21));
        // central box 3.6..6.0 x 2.3..3.9
        assertTrue(m.isObstacleAt(4.8, 3.1));
        assertTrue(m.isObstacleAt(3.61, 2.31));
        assertTrue(m.isObstacleAt(5.99, 3.89));
        assertFalse(m.isObstacleAt(3.59, 3.1));
        assertFalse(m.isObstacleAt(6.01, 3.1));
        assertFalse(m.isObstacleAt(4.8, 2.29));
        assertFalse(m.isObstacleAt(4.8, 3.91));
        // pillars 4.8..5.2 x 0.6..1.0 and 4.6..5.0 x 5.2..5.6
        assertTrue(m.isObstacleAt(5.0, 0.8));
        assertTrue(m.isObstacleAt(4.81, 0.61));
        assertFalse(m.isObstacleAt(4.79, 0.8));
        assertFalse(m.isObstacleAt(5.21, 0.8));
        assertTrue(m.isObstacleAt(4.8, 5.4));
        assertTrue(m.isObstacleAt(4.99, 5.59));
        assertFalse(m.isObstacleAt(5.01, 5.4));
        assertFalse(m.isObstacleAt(4.8, 5.61));
        // start and waypoints are free with room for the robot
        assertTrue(m.clearanceM(0.8, 0.8, 1.0) > 0.5);
        for (Point2d w : s.waypoints()) {
            assertTrue(m.clearanceM(w.xM(), w.yM(), 1.0) > 0.5, w.toString());
        }
        assertEquals(0.6, m.clearanceM(4.2, 0.8, 1.0), 1e-9);
    }
}
