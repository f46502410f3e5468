package io.rtaware.nav.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.nav.logic.ObstacleAvoider;
import io.rtaware.core.testing.TaskHarness;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.MotionRequest;
import io.rtaware.robot.msg.RobotKeys;
import org.junit.jupiter.api.Test;

class ObstacleAvoidanceTaskTest {

    private static final long MS = 1_000_000L;

    @Test
    void avoidsOnFreshScansAndStopsWhenBlind() {
        TaskHarness h = TaskHarness.builder().input(RobotKeys.LASER)
                .task("obstacle", new ObstacleAvoidanceTask(new ObstacleAvoider(0.4, 0.6, 0.25, 0.03, 0.5), 300 * MS))
                .build();
        h.cycle("obstacle", 0);
        MotionRequest req = h.read(RobotKeys.MOTION_AVOID);
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
        h.publish(RobotKeys.LASER, scan, 50 * MS);
        h.cycle("obstacle", 100 * MS);
        assertFalse(h.read(RobotKeys.MOTION_AVOID).active, "open space: request nothing");

        scan.rangesM[2] = 0.3f; // left
        h.publish(RobotKeys.LASER, scan, 150 * MS);
        h.cycle("obstacle", 200 * MS);
        assertEquals(-0.5, h.read(RobotKeys.MOTION_AVOID).omegaRadPerSec);

        h.cycle("obstacle", 500 * MS); // scan 350 ms old
        req = h.read(RobotKeys.MOTION_AVOID);
        assertTrue(req.active);
        assertEquals(0.0, req.vxMps);
        assertEquals(0.0, req.omegaRadPerSec);
    }
}
