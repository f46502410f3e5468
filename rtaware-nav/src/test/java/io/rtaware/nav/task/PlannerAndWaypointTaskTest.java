package io.rtaware.nav.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.data.Key;
import io.rtaware.nav.NavConfig;
import io.rtaware.nav.NavKeys;
import io.rtaware.nav.logic.DijkstraPlanner;
import io.rtaware.nav.logic.PathFollower;
import io.rtaware.nav.logic.WaypointSequencer;
import io.rtaware.nav.testing.FakeStore;
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
    private final FakeStore store = new FakeStore();
    private final Odometry odom = new Odometry();

    private FakeStore.Bound planner() throws Exception {
        return store.bind("planner", new DijkstraPlannerTask(keys.map(), keys.path(), List.of(keys.goalsWaypoint()),
                new DijkstraPlanner(30 * 20, 0.25, 2.0), 0.2));
    }

    private FakeStore.Bound waypoint(WaypointPlannerTask task) throws Exception {
        return store.bind("waypoint", task);
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
        store.write(RobotKeys.ODOMETRY, odom, nowNs);
    }

    @Test
    void waypointRequestsGoalsPlannerPlansAndTheCourseCompletes() throws Exception {
        OccupancyGrid map = new OccupancyGrid(600);
        map.setGeometry(30, 20, 0.1, 0, 0);
        java.util.Arrays.fill(map.cells, 0, 600, OccupancyGrid.FREE);
        store.write(keys.map(), map, 0);
        WaypointPlannerTask wpTask = waypointTask(null);
        FakeStore.Bound wp = waypoint(wpTask);
        FakeStore.Bound pl = planner();

        pose(0.5, 1.0, 0);
        wp.cycle(0);
        GoalSet goals = store.read(keys.goalsWaypoint());
        assertEquals(1, goals.count());
        assertEquals(2.0, goals.xM[0]);
        MotionRequest req = store.read(RobotKeys.MOTION_WAYPOINT);
        assertTrue(req.active, "heads for the waypoint before any path");
        assertEquals(0.1, req.vxMps, 1e-12);

        pl.cycle(0);
        PlannedPath path = store.read(keys.path());
        assertTrue(path.valid);
        assertEquals(goals.id[0], path.goalId);
        assertEquals(1.5, path.costM, 0.11);
        long plans = path.planCount;
        pl.cycle(100 * MS);
        assertEquals(plans, store.read(keys.path()).planCount, "nothing changed: no replan");

        pose(1.9, 1.0, 200 * MS);
        wp.cycle(200 * MS);
        CourseStatus course = store.read(keys.course());
        assertEquals(1, course.waypointsReached);
        assertEquals(1, course.currentIndex);
        assertEquals(0.5, course.distanceToGoalM, 0.11);
        assertEquals(1, store.read(keys.goalsWaypoint()).count(), "the reached goal was replaced by the next");
        assertEquals(0.5, store.read(keys.goalsWaypoint()).yM[0]);
        pl.cycle(200 * MS);
        assertEquals(0.5, store.read(keys.path()).goalYM, "replanned for the new goal");

        pose(2.0, 0.6, 300 * MS);
        wp.cycle(300 * MS);
        course = store.read(keys.course());
        assertTrue(course.done);
        assertEquals(2, course.waypointsReached);
        assertEquals(0, store.read(keys.goalsWaypoint()).count(), "finish goal removed");
        assertFalse(store.read(RobotKeys.MOTION_WAYPOINT).active, "done: request nothing");
        assertTrue(wpTask.progress().done());
        pl.cycle(300 * MS);
        assertFalse(store.read(keys.path()).valid, "no goal, no path");
    }

    @Test
    void anotherTaskCanReplaceTheCourse() throws Exception {
        FakeStore.Bound wp = waypoint(waypointTask(keys.waypointsIn()));
        pose(0.5, 1.0, 0);
        wp.cycle(0);
        GoalSet replacement = new GoalSet(4);
        replacement.add(1, 0.5, 0.5);
        store.write(keys.waypointsIn(), replacement, 50 * MS);
        wp.cycle(100 * MS);
        CourseStatus course = store.read(keys.course());
        assertEquals(1, course.waypointsTotal);
        assertEquals(0.5, course.goalYM);
        assertEquals(0.5, store.read(keys.goalsWaypoint()).yM[0]);
    }

    @Test
    void staleOdometryRequestsNothing() throws Exception {
        FakeStore.Bound wp = waypoint(waypointTask(null));
        pose(0.5, 1.0, 0);
        wp.cycle(600 * MS);
        assertFalse(store.read(RobotKeys.MOTION_WAYPOINT).active);
        assertFalse(store.read(keys.course()).positionKnown);
    }
}
