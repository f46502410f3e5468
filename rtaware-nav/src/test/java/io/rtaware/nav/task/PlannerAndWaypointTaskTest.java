package io.rtaware.nav.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.data.Key;
import io.rtaware.core.testing.TaskHarness;
import io.rtaware.nav.NavConfig;
import io.rtaware.nav.NavKeys;
import io.rtaware.nav.logic.DijkstraPlanner;
import io.rtaware.nav.logic.PathFollower;
import io.rtaware.nav.logic.WaypointSequencer;
import io.rtaware.robot.geometry.Point2d;
import io.rtaware.robot.msg.CourseStatus;
import io.rtaware.robot.msg.GoalSet;
import io.rtaware.robot.msg.MotionRequest;
import io.rtaware.robot.msg.OccupancyGrid;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.robot.msg.PlannedPath;
import io.rtaware.robot.msg.RobotKeys;
import java.util.List;
import org.junit.jupiter.api.Test;

class PlannerAndWaypointTaskTest {

    private static final long MS = 1_000_000L;

    private final NavConfig config = NavConfig.builder().grid(0.1, 0, 0, 3, 2)
            .waypoints(List.of(new Point2d(2.0, 1.0), new Point2d(2.0, 0.5))).externalWaypoints(true).build();
    private final NavKeys keys = new NavKeys(config);
    private final Odometry odom = new Odometry();
    private TaskHarness h;

    private DijkstraPlannerTask planner() {
        return new DijkstraPlannerTask(keys.map(), keys.path(), List.of(keys.goalsWaypoint()),
                new DijkstraPlanner(30 * 20, 0.25, 2.0), 0.2);
    }

    private WaypointPlannerTask waypointTask(Key<GoalSet> in) {
        GoalSet course = new GoalSet(4);
        course.add(1, 2.0, 1.0);
        course.add(2, 2.0, 0.5);
        return new WaypointPlannerTask(keys.goalsWaypoint(), keys.path(), keys.course(), in, course,
                new WaypointSequencer(8, 0.25), new PathFollower(0.1, 0.5, 0.3, 0.8), 500 * MS);
    }

    private void pose(double x, double y, long nowNs) {
        odom.xM = x;
        odom.yM = y;
        odom.yawRad = 0;
        h.publish(RobotKeys.ODOMETRY, odom, nowNs);
    }

    @Test
    void waypointRequestsGoalsPlannerPlansAndTheCourseCompletes() {
        OccupancyGrid map = new OccupancyGrid(600);
        map.setGeometry(30, 20, 0.1, 0, 0);
        java.util.Arrays.fill(map.cells, 0, 600, OccupancyGrid.FREE);
        WaypointPlannerTask wpTask = waypointTask(null);
        h = TaskHarness.builder().input(keys.map()).input(RobotKeys.ODOMETRY)
                .task("waypoint", wpTask).task("planner", planner()).build();
        h.publish(keys.map(), map, 0);

        pose(0.5, 1.0, 0);
        h.cycle("waypoint", 0);
        GoalSet goals = h.read(keys.goalsWaypoint());
        assertEquals(1, goals.count());
        assertEquals(2.0, goals.xM[0]);
        MotionRequest req = h.read(RobotKeys.MOTION_WAYPOINT);
        assertTrue(req.active, "heads for the waypoint before any path");
        assertEquals(0.1, req.vxMps, 1e-12);

        h.cycle("planner", 0);
        PlannedPath path = h.read(keys.path());
        assertTrue(path.valid);
        assertEquals(goals.id[0], path.goalId);
        assertEquals(1.5, path.costM, 0.11);
        long plans = path.planCount;
        h.cycle("planner", 100 * MS);
        assertEquals(plans, h.read(keys.path()).planCount, "nothing changed: no replan");

        pose(1.9, 1.0, 200 * MS);
        h.cycle("waypoint", 200 * MS);
        CourseStatus course = h.read(keys.course());
        assertEquals(1, course.waypointsReached);
        assertEquals(1, course.currentIndex);
        assertEquals(0.5, course.distanceToGoalM, 0.11);
        assertEquals(1, h.read(keys.goalsWaypoint()).count(), "the reached goal was replaced by the next");
        assertEquals(0.5, h.read(keys.goalsWaypoint()).yM[0]);
        h.cycle("planner", 200 * MS);
        assertEquals(0.5, h.read(keys.path()).goalYM, "replanned for the new goal");

        pose(2.0, 0.6, 300 * MS);
        h.cycle("waypoint", 300 * MS);
        course = h.read(keys.course());
        assertTrue(course.done);
        assertEquals(2, course.waypointsReached);
        assertEquals(0, h.read(keys.goalsWaypoint()).count(), "finish goal removed");
        assertFalse(h.read(RobotKeys.MOTION_WAYPOINT).active, "done: request nothing");
        assertTrue(wpTask.progress().done());
        h.cycle("planner", 300 * MS);
        assertFalse(h.read(keys.path()).valid, "no goal, no path");
    }

    @Test
    void anotherTaskCanReplaceTheCourse() {
        h = TaskHarness.builder().input(RobotKeys.ODOMETRY).input(keys.path()).input(keys.waypointsIn())
                .task("waypoint", waypointTask(keys.waypointsIn())).build();
        pose(0.5, 1.0, 0);
        h.cycle("waypoint", 0);
        GoalSet replacement = new GoalSet(4);
        replacement.add(1, 0.5, 0.5);
        h.publish(keys.waypointsIn(), replacement, 50 * MS);
        h.cycle("waypoint", 100 * MS);
        CourseStatus course = h.read(keys.course());
        assertEquals(1, course.waypointsTotal);
        assertEquals(0.5, course.goalYM);
        assertEquals(0.5, h.read(keys.goalsWaypoint()).yM[0]);
    }

    @Test
    void staleOdometryRequestsNothing() {
        h = TaskHarness.builder().input(RobotKeys.ODOMETRY).input(keys.path())
                .task("waypoint", waypointTask(null)).build();
        pose(0.5, 1.0, 0);
        h.cycle("waypoint", 600 * MS);
        assertFalse(h.read(RobotKeys.MOTION_WAYPOINT).active);
        assertFalse(h.read(keys.course()).positionKnown);
    }
}
