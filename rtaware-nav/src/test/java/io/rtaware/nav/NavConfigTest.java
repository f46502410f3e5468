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
        assertEquals(50 * MS, c.periods().mediatorNs(), "the faster of obstacle and waypoint");
        assertEquals(150 * MS, c.maxAges().avoidRequestNs());
        assertEquals(250 * MS, c.maxAges().waypointRequestNs());
        assertEquals(0.05, c.grid().resolutionM());
        assertEquals(400, c.grid().widthCells());
        assertEquals(0.25, c.inflationRadiusM(), 1e-12);
        for (Behavior b : Behavior.values()) {
            assertEquals(b.defaultPeriodNs(), c.periods().ns(b), b.taskName());
        }
    }

    @Test
    void periodsByNameAndTheirTasks() {
        NavConfig c = NavConfig.builder().waypoints(COURSE)
                .periodsNs(Map.of("obstacle", 10 * MS, "waypoint", 20 * MS)).build();
        assertEquals(10 * MS, c.periods().mediatorNs());
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
    void behaviorsCarryTheirNamesAndSet4Periods() {
        assertEquals(List.of("waypoint", "obstacle", "occupancy", "planner"), Behavior.taskNames());
        assertEquals(Map.of("waypoint", 100 * MS, "obstacle", 50 * MS, "occupancy", 100 * MS, "planner", 100 * MS),
                Behavior.defaultPeriodsNs());
        assertEquals(Behavior.PLANNER, Behavior.ofTaskName("planner"));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Behavior.ofTaskName("mapper"));
        assertEquals("unknown behavior 'mapper' (known: waypoint, obstacle, occupancy, planner)", e.getMessage());
        assertEquals(List.of("waypoint", "obstacle", "occupancy", "planner", "mediator"), NavConfig.TASK_NAMES);
    }

    @Test
    void theAvoiderDeclaresItsReactionFromTheRobotLimits() {
        NavConfig c = NavConfig.builder().waypoints(COURSE).topSpeedMps(0.2).reactionLimits(0.026, 76_600_000L).build();
        io.rtaware.core.monitor.Monitor.Builder b = io.rtaware.core.monitor.Monitor.builder(
                new io.rtaware.core.time.ManualClock());
        new NavController(c).taskSpecs().forEach(b::task);
        b.task(new TaskSpec("sim", Schedule.periodic(10 * MS), io.rtaware.core.task.ErrorPolicy.CONTINUE,
                new io.rtaware.core.task.Task() {
                    @Override
                    public void initialize(io.rtaware.core.task.TaskSetup setup) {
                        setup.produce(io.rtaware.robot.msg.RobotKeys.LASER);
                        setup.produce(io.rtaware.robot.msg.RobotKeys.ODOMETRY);
                        setup.consume(io.rtaware.robot.msg.RobotKeys.MOTOR);
                    }

                    @Override
                    public void execute(long nowNs) {
                    }
                }));
        io.rtaware.core.monitor.Monitor monitor = b.build();
        monitor.startStepped().runUntil(100 * MS);
        assertEquals(new io.rtaware.core.task.ReactionConstraint("laser", 0.2, 0.026, 0.4 - 0.2, 76.6),
                monitor.stop().task("obstacle").reaction());
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

    /** Issue 24: a hostile nav_config in a recording overflowed these checks. */
    @Test
    void hostileSizesAndPeriodsCannotOverflowTheirChecks() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> NavConfig.builder().waypoints(List.of(new Point2d(1, 1))).grid(1e-300, 0, 0, 1e300, 1e300).build());
        assertTrue(e.getMessage().contains("more than " + NavConfig.MAX_GRID_CELLS), e.getMessage());
        e = assertThrows(IllegalArgumentException.class,
                () -> NavConfig.builder().waypoints(List.of(new Point2d(1, 1))).grid(1e-10, 0, 0, 1e10, 1e10).build());
        assertTrue(e.getMessage().contains("cells, more than"), e.getMessage());
        NavConfig slow = NavConfig.builder().waypoints(List.of(new Point2d(1, 1)))
                .periodNs(Behavior.OBSTACLE, Long.MAX_VALUE / 2 + 1)
                .periodNs(Behavior.WAYPOINT, Long.MAX_VALUE / 2 + 1).build();
        assertEquals(Long.MAX_VALUE, slow.maxAges().avoidRequestNs(), "saturated, not wrapped to a negative age");
        assertEquals(Long.MAX_VALUE, slow.maxAges().waypointRequestNs());
    }
}
