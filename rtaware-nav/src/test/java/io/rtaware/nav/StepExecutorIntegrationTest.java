package io.rtaware.nav;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.data.Input;
import io.rtaware.core.data.Output;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.monitor.StepExecutor;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.ManualClock;
import io.rtaware.nav.testing.SimRoom;
import io.rtaware.robot.geometry.Point2d;
import io.rtaware.robot.msg.CourseStatus;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.robot.msg.RobotKeys;
import io.rtaware.robot.msg.VelocityCommand;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The controller on the real monitor and its step executor (no threads, manual clock), with a
 * simulator task standing in for the Player data task: the data graph verifies, the course
 * completes without collision, no deadline is missed, and the map survives termination.
 */
class StepExecutorIntegrationTest {

    private static final long MS = 1_000_000L;

    /** Produces laser (every 100 ms) and odometry, consumes motor, moves the kinematic robot. */
    private static final class SimTask implements Task {
        private final SimRoom room;
        private final long periodNs;
        private Input<VelocityCommand> motor;
        private Output<LaserScan> laser;
        private Output<Odometry> odometry;
        private long startNs = -1;
        private long lastNs;

        SimTask(SimRoom room, long periodNs) {
            this.room = room;
            this.periodNs = periodNs;
        }

        @Override
        public void initialize(TaskSetup setup) {
            motor = setup.consume(RobotKeys.MOTOR);
            laser = setup.produce(RobotKeys.LASER);
            odometry = setup.produce(RobotKeys.ODOMETRY);
        }

        @Override
        public void execute(long nowNs) {
            if (startNs < 0) {
                startNs = nowNs;
                lastNs = nowNs;
            }
            VelocityCommand cmd = motor.value();
            room.step(cmd.vxMps, cmd.omegaRadPerSec, (nowNs - lastNs) / 1e9);
            lastNs = nowNs;
            room.odometry(odometry.value());
            odometry.publish();
            if ((nowNs - startNs) % (100 * MS) == 0) {
                room.scan(laser.value());
                laser.publish();
            }
        }

        long periodNs() {
            return periodNs;
        }
    }

    @Test
    void completesTheCourseOnTheStepExecutor() {
        SimRoom room = new SimRoom(0.2).rect(0, 0, 6, 4).rect(2.5, 1.4, 3.5, 2.6);
        room.xM = 0.8;
        room.yM = 2.0;
        NavController nav = new NavController(NavConfig.builder()
                .grid(0.05, -1, -1, 8, 6)
                .waypoints(List.of(new Point2d(5.2, 2.0), new Point2d(3.0, 3.4), new Point2d(0.8, 2.0)))
                .build());
        SimTask sim = new SimTask(room, 10 * MS);
        Monitor.Builder builder = Monitor.builder(new ManualClock());
        builder.task(new TaskSpec("sim", Schedule.periodic(sim.periodNs()), io.rtaware.core.task.ErrorPolicy.STOP_ALL,
                sim));
        nav.taskSpecs().forEach(builder::task);
        Monitor monitor = builder.build();
        StepExecutor step = monitor.startStepped();
        CourseStatus course = new CourseStatus();
        for (int s = 0; s < 400 && !course.done; s++) {
            step.runFor(1000 * MS);
            monitor.read(nav.keys().course(), course);
        }
        monitor.stop();
        assertTrue(course.done, "course done; reached " + course.waypointsReached);
        assertEquals(0, room.collisions);
        for (String task : NavConfig.TASK_NAMES) {
            assertEquals(0, monitor.counters(task).misses(), task + " misses");
            assertEquals(0, monitor.counters(task).errors(), task + " errors");
        }
        assertTrue(nav.mediatorCounts().waypoint() > 0);
        assertTrue(nav.finalMap().isPresent(), "map kept at termination");
        assertEquals(3, nav.courseProgress().waypointsReached());
    }
}
