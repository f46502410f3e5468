package io.rtaware.nav.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.nav.logic.ObstacleAvoider;
import io.rtaware.nav.testing.FakeStore;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.MotionRequest;
import io.rtaware.robot.msg.RobotKeys;
import org.junit.jupiter.api.Test;

class ObstacleAvoidanceTaskTest {

    private static final long MS = 1_000_000L;

    @Test
    void avoidsOnFreshScansAndStopsWhenBlind() throws Exception {
        FakeStore store = new FakeStore();
        FakeStore.Bound task = store.bind("obstacle",
                new ObstacleAvoidanceTask(new ObstacleAvoider(0.4, 0.6, 0.25, 0.03, 0.5), 300 * MS, null));
        task.cycle(0);
        MotionRequest req = store.read(RobotKeys.MOTION_AVOID);
        assertTrue(req.active, "no scan yet: take control");
        assertEquals(0.0, req.vxMps);
        assertEquals(0.0, req.omegaRadPerSec);

        LaserScan scan = new LaserScan(3);
        scan.setCount(3);
        scan.minAngleRad = -0.2;
        scan.maxAngleRad = 0.2;
        scan.maxRangeM = 5.6;
        scan.rangesM[0] = 3f;
        scan.rangesM[1] = 3f;
        scan.rangesM[2] = 3f;
        store.write(RobotKeys.LASER, scan, 50 * MS);
        task.cycle(100 * MS);
        assertFalse(store.read(RobotKeys.MOTION_AVOID).active, "open space: request nothing");

        scan.rangesM[2] = 0.3f; // left
        store.write(RobotKeys.LASER, scan, 150 * MS);
        task.cycle(200 * MS);
        assertEquals(-0.5, store.read(RobotKeys.MOTION_AVOID).omegaRadPerSec);

        task.cycle(500 * MS); // scan 350 ms old
        req = store.read(RobotKeys.MOTION_AVOID);
        assertTrue(req.active);
        assertEquals(0.0, req.vxMps);
        assertEquals(0.0, req.omegaRadPerSec);
    }
}
