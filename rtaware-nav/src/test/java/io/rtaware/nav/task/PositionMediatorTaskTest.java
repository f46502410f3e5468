package io.rtaware.nav.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.testing.TaskHarness;
import io.rtaware.robot.msg.MediatorDecision;
import io.rtaware.robot.msg.MotionRequest;
import io.rtaware.robot.msg.RobotKeys;
import io.rtaware.robot.msg.VelocityCommand;
import org.junit.jupiter.api.Test;

class PositionMediatorTaskTest {

    private static final long MS = 1_000_000L;

    @Test
    void priorityStaleStopAndCounts() {
        PositionMediatorTask task = new PositionMediatorTask(150 * MS, 250 * MS);
        TaskHarness h = TaskHarness.builder().input(RobotKeys.MOTION_AVOID).input(RobotKeys.MOTION_WAYPOINT)
                .task("mediator", task).build();
        MotionRequest avoid = new MotionRequest();
        MotionRequest waypoint = new MotionRequest();

        h.cycle("mediator", 0);
        assertTrue(h.read(RobotKeys.MOTOR).isStop(), "nothing written yet: stop");
        assertEquals(1, task.counts().staleStops());
        assertEquals(MediatorDecision.STALE_STOP, h.read(RobotKeys.MEDIATOR_DECISION).winner);

        avoid.release();
        waypoint.request(0.1, 0.2);
        h.publish(RobotKeys.MOTION_AVOID, avoid, 0);
        h.publish(RobotKeys.MOTION_WAYPOINT, waypoint, 0);
        h.cycle("mediator", 50 * MS);
        VelocityCommand motor = h.read(RobotKeys.MOTOR);
        assertEquals(0.1, motor.vxMps);
        assertEquals(0.2, motor.omegaRadPerSec);
        assertEquals(MediatorDecision.WAYPOINT, h.read(RobotKeys.MEDIATOR_DECISION).winner, "the winner of each cycle");

        avoid.request(0.03, -0.5);
        h.publish(RobotKeys.MOTION_AVOID, avoid, 100 * MS);
        h.cycle("mediator", 100 * MS);
        assertEquals(-0.5, h.read(RobotKeys.MOTOR).omegaRadPerSec);
        assertEquals(MediatorDecision.OBSTACLE, h.read(RobotKeys.MEDIATOR_DECISION).winner);

        // The avoider misses its deadlines: at 300 ms its request is 200 ms old (> 150 ms).
        h.cycle("mediator", 300 * MS);
        assertTrue(h.read(RobotKeys.MOTOR).isStop(), "a stale safety request stops the robot");

        PositionMediatorTask.MediatorCounts counts = task.counts();
        assertEquals(1, counts.obstacle());
        assertEquals(1, counts.waypoint());
        assertEquals(2, counts.stop());
        assertEquals(2, counts.staleStops());
        assertEquals(300 * MS, counts.lastStaleStopNs());
    }
}
