package io.rtaware.nav;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.testing.TaskHarness;
import io.rtaware.nav.map.PgmMapWriter;
import io.rtaware.nav.task.PositionMediatorTask;
import io.rtaware.nav.testing.SimRoom;
import io.rtaware.robot.geometry.Point2d;
import io.rtaware.robot.msg.CourseStatus;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.OccupancyGrid;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.robot.msg.RobotKeys;
import io.rtaware.robot.msg.VelocityCommand;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The whole controller, its five tasks from {@link NavController#taskSpecs()}, driven in world
 * time by a step loop over a fake store and a kinematic room with a box between the start and
 * the first waypoint: the course must complete without collision, at the paper's period sets.
 */
class ClosedLoopTest {

    private static final long STEP_NS = 10_000_000L;
    private static final long LASER_PERIOD_NS = 100_000_000L;

    @TempDir
    Path tmp;

    @ParameterizedTest(name = "periods waypoint={0} obstacle={1} occupancy={2} planner={3} ms")
    @CsvSource({"10,10,10,10", "100,10,100,100", "50,50,50,50", "100,50,100,100", "100,100,100,100"})
    void completesTheCourseAroundTheBox(long waypointMs, long obstacleMs, long occupancyMs, long plannerMs)
            throws Exception {
        SimRoom room = new SimRoom(0.2).rect(0, 0, 6, 4).rect(2.5, 1.4, 3.5, 2.6);
        room.xM = 0.8;
        room.yM = 2.0;
        NavConfig config = NavConfig.builder()
                .periodsNs(Map.of("waypoint", waypointMs * 1_000_000, "obstacle", obstacleMs * 1_000_000,
                        "occupancy", occupancyMs * 1_000_000, "planner", plannerMs * 1_000_000))
                .grid(0.05, -1, -1, 8, 6)
                .waypoints(List.of(new Point2d(5.2, 2.0), new Point2d(3.0, 3.4), new Point2d(0.8, 2.0)))
                .build();
        NavController nav = new NavController(config);
        TaskHarness.Builder harness = TaskHarness.builder().input(RobotKeys.ODOMETRY).input(RobotKeys.LASER);
        List<String> names = new ArrayList<>();
        List<Long> periods = new ArrayList<>();
        for (TaskSpec spec : nav.taskSpecs()) {
            harness.task(spec.name(), spec.task());
            names.add(spec.name());
            periods.add(((Schedule.Periodic) spec.schedule()).periodNs());
        }
        TaskHarness h = harness.build();
        LaserScan scan = new LaserScan(SimRoom.BEAMS);
        Odometry odom = new Odometry();
        long limitNs = 400_000_000_000L;
        long now = 0;
        boolean done = false;
        while (now < limitNs && !done) {
            room.odometry(odom);
            h.publish(RobotKeys.ODOMETRY, odom, now);
            if (now % LASER_PERIOD_NS == 0) {
                room.scan(scan);
                h.publish(RobotKeys.LASER, scan, now);
            }
            for (int i = 0; i < names.size(); i++) {
                if (now % periods.get(i) == 0) {
                    assertNull(h.cycle(names.get(i), now), "cycle of " + names.get(i));
                }
            }
            VelocityCommand cmd = h.read(RobotKeys.MOTOR);
            assertTrue(Math.abs(cmd.vxMps) <= config.topSpeedMps() + 1e-9, "speed within the top speed");
            assertTrue(Math.abs(cmd.omegaRadPerSec) <= config.maxOmegaRadPerSec() + 1e-9, "turn rate within limit");
            room.step(cmd.vxMps, cmd.omegaRadPerSec, STEP_NS / 1e9);
            CourseStatus course = h.read(nav.keys().course());
            done = course.done;
            now += STEP_NS;
        }
        h.stop();
        CourseStatus course = h.read(nav.keys().course());
        assertTrue(course.done, "course done within the limit; reached " + course.waypointsReached
                + " at " + room.xM + "," + room.yM);
        assertEquals(3, course.waypointsReached);
        assertEquals(0, room.collisions, "collisions");
        assertTrue(Math.hypot(room.xM - 0.8, room.yM - 2.0) <= config.goalToleranceM() + 0.02, "at the finish");
        PositionMediatorTask.MediatorCounts counts = nav.mediatorCounts();
        assertTrue(counts.waypoint() > 0, "waypoint planner drove");
        assertEquals(nav.courseProgress().waypointsReached(), 3);
        OccupancyGrid map = nav.finalMap().orElseThrow();
        assertEquals(OccupancyGrid.OCCUPIED, map.cell(map.cellX(2.5), map.cellY(2.0)), "box edge mapped");
        Path yaml = PgmMapWriter.write(map, tmp, "map");
        assertTrue(Files.readString(yaml).contains("resolution: 0.05"));
        System.out.printf("periods %d/%d/%d/%d: done in %.1f s, mediator %s%n", waypointMs, obstacleMs,
                occupancyMs, plannerMs, now / 1e9, counts);
    }
}
