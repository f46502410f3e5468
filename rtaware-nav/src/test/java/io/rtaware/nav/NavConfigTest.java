package io.rtaware.nav;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.robot.geometry.Point2d;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

class NavConfigTest {

    private static final long MS = 1_000_000L;
    private static final List<Point2d> COURSE = List.of(new Point2d(1, 1));

    @Test
    void defaultsAreThePapersSet4() {
        NavConfig c = NavConfig.builder().waypoints(COURSE).build();
        assertEquals(100 * MS, c.periodNs("waypoint"));
        assertEquals(50 * MS, c.periodNs("obstacle"));
        assertEquals(100 * MS, c.periodNs("occupancy"));
        assertEquals(100 * MS, c.periodNs("planner"));
        assertEquals(50 * MS, c.mediatorPeriodNs(), "the faster of obstacle and waypoint");
        assertEquals(150 * MS, c.avoidMaxAgeNs());
        assertEquals(250 * MS, c.waypointMaxAgeNs());
        assertEquals(0.05, c.gridResolutionM());
        assertEquals(400, c.gridWidthCells());
        assertEquals(0.25, c.inflationRadiusM(), 1e-12);
    }

    @Test
    void periodsByNameAndTheirTasks() {
        NavConfig c = NavConfig.builder().waypoints(COURSE)
                .periodsNs(Map.of("obstacle", 10 * MS, "waypoint", 20 * MS)).build();
        assertEquals(10 * MS, c.mediatorPeriodNs());
        NavController nav = new NavController(c);
        List<TaskSpec> specs = nav.taskSpecs();
        assertEquals(NavConfig.TASK_NAMES, specs.stream().map(TaskSpec::name).toList());
        assertEquals(10 * MS, ((Schedule.Periodic) specs.get(1).schedule()).periodNs());
        assertEquals("map", nav.keys().map().name());
        assertEquals("path", nav.keys().path().name());
        assertEquals("course", nav.keys().course().name());
        assertEquals("goals.waypoint", nav.keys().goalsWaypoint().name());
        assertTrue(nav.finalMap().isEmpty());
        assertEquals(0, nav.mediatorCounts().obstacle());
    }

    @Test
    void badValuesAreNamed() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> NavConfig.builder().waypoints(COURSE).periodsNs(Map.of("mapper", 10 * MS)));
        assertTrue(e.getMessage().contains("mapper"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class,
                () -> NavConfig.builder().waypoints(COURSE).periodsNs(Map.of("planner", 0L)));
        assertTrue(e.getMessage().contains("planner") && e.getMessage().contains("0"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class,
                () -> NavConfig.builder().waypoints(COURSE).topSpeedMps(-0.1).build());
        assertTrue(e.getMessage().contains("topSpeedMps") && e.getMessage().contains("-0.1"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> NavConfig.builder().build());
        assertTrue(e.getMessage().contains("waypoints"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class,
                () -> NavConfig.builder().waypoints(COURSE).grid(0.001, 0, 0, 100, 100).build());
        assertTrue(e.getMessage().contains("cells"), e.getMessage());
    }
}
