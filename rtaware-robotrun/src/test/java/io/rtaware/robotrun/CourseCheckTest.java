package io.rtaware.robotrun;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.robot.geometry.Point2d;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.sim.map.OccupancyMap;
import io.rtaware.sim.map.OccupancyMap.CellState;
import io.rtaware.sim.scenario.Scenario;
import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

class CourseCheckTest {

    /** 20 x 20 cells of 0.1 m from (0, 0): free, with a closed ring of obstacles around cells 12..16. */
    private static OccupancyMap ringMap() {
        int n = 20;
        CellState[] cells = new CellState[n * n];
        Arrays.fill(cells, CellState.FREE);
        for (int i = 11; i <= 17; i++) {
            cells[11 * n + i] = CellState.OCCUPIED;
            cells[17 * n + i] = CellState.OCCUPIED;
            cells[i * n + 11] = CellState.OCCUPIED;
            cells[i * n + 17] = CellState.OCCUPIED;
        }
        cells[2 * n + 2] = CellState.OCCUPIED;
        return new OccupancyMap("ring", n, n, 0.1, 0, 0, cells);
    }

    private static Scenario course(Pose2d start, Point2d... waypoints) {
        return new Scenario("t", Optional.of(ringMap()), start, List.of(waypoints), 0.2, 60);
    }

    @Test
    void aDrivableCourseHasNoWarning() {
        assertEquals(List.of(), CourseCheck.warnings(course(new Pose2d(0.05, 0.05, 0), new Point2d(1.9, 0.5))));
    }

    @Test
    void offTheMapInsideAnObstacleAndEnclosedAreEachNamed() {
        List<String> w = CourseCheck.warnings(course(new Pose2d(0.05, 0.05, 0), new Point2d(5, 5), new Point2d(0.25, 0.25),
                new Point2d(1.45, 1.45), new Point2d(0.5, 1.9)));
        assertEquals(3, w.size(), w.toString());
        assertTrue(w.get(0).startsWith("waypoint 1 (5.00, 5.00) lies off the map (it spans x 0.00..2.00 m"), w.get(0));
        assertEquals("waypoint 2 (0.25, 0.25) lies inside an obstacle", w.get(1));
        assertTrue(w.get(2).startsWith("waypoint 3 (1.45, 1.45) lies in a region enclosed from the start"), w.get(2));
    }

    @Test
    void aStartInsideTheRingMakesEverythingOutsideUnreachable() {
        List<String> w = CourseCheck.warnings(course(new Pose2d(1.45, 1.45, 0), new Point2d(0.5, 0.5)));
        assertEquals(List.of("waypoint 1 (0.50, 0.50) lies in a region enclosed from the start (no free path on the map leads there)"), w);
        assertTrue(CourseCheck.warnings(course(new Pose2d(0.25, 0.25, 0), new Point2d(0.5, 0.5))).get(0)
                .startsWith("the start pose (0.25, 0.25) lies inside an obstacle"));
    }
}
