package io.rtaware.nav.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.nav.testing.FakeStore;
import io.rtaware.robot.msg.MotionRequest;
import io.rtaware.robot.msg.RobotKeys;
import io.rtaware.robot.msg.VelocityCommand;
import org.junit.jupiter.api.Test;

class PositionMediatorTaskTest {

    private static final long MS = 1_000_000L;

    @Test
    void priorityStaleStopAndCounts() throws Exception {
        FakeStore store = new FakeStore();
        PositionMediatorTask task = new PositionMediatorTask(150 * MS, 250 * MS);
        FakeStore.Bound mediator = store.bind("mediator", task);
        MotionRequest avoid = new MotionRequest();
        MotionRequest waypoint = new MotionRequest();

        mediator.cycle(0);
        assertTrue(store.read(RobotKeys.MOTOR).isStop(), "nothing written yet: stop");
        assertEquals(1, task.counts().staleStops());

        avoid.release();
        waypoint.request(0.1, 0.2);
        store.write(RobotKeys.MOTION_AVOID, avoid, 0);
        store.write(RobotKeys.MOTION_WAYPOINT, waypoint, 0);
        mediator.cycle(50 * MS);
        VelocityCommand motor = store.read(RobotKeys.MOTOR);
        assertEquals(0.1, motor.vxMps);
        assertEquals(0.2, motor.omegaRadPerSec);

        avoid.request(0.03, -0.5);
        store.write(RobotKeys.MOTION_AVOID, avoid, 100 * MS);
        mediator.cycle(100 * MS);
        assertEquals(-0.5, store.read(RobotKeys.MOTOR).omegaRadPerSec);

        // The avoider misses its deadlines: at 300 ms its request is 200 ms old (> 150 ms).
        mediator.cycle(300 * MS);
        assertTrue(store.read(RobotKeys.MOTOR).isStop(), "a stale safety request stops the robot");

        PositionMediatorTask.MediatorCounts counts = task.counts();
        assertEquals(1, counts.obstacle());
        assertEquals(1, counts.waypoint());
        assertEquals(2, counts.stop());
        assertEquals(2, counts.staleStops());
        assertEquals(300 * MS, counts.lastStaleStopNs());
    }
}
