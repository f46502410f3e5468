package io.rtaware.nav.logic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.robot.msg.MotionRequest;
import org.junit.jupiter.api.Test;

class PathFollowerTest {

    private final PathFollower follower = new PathFollower(0.1, 0.5, 0.3, 0.8);
    private final MotionRequest out = new MotionRequest();

    @Test
    void straightAheadDrivesAtTopSpeed() {
        follower.driveTo(0, 0, 0, 2, 0, out);
        assertTrue(out.active);
        assertEquals(0.1, out.vxMps, 1e-12);
        assertEquals(0.0, out.omegaRadPerSec, 1e-12);
    }

    @Test
    void turnsTowardAGoalOnTheLeftOrRight() {
        follower.driveTo(0, 0, 0, 2, 0.5, out);
        assertTrue(out.omegaRadPerSec > 0);
        assertTrue(out.vxMps > 0 && out.vxMps <= 0.1);
        follower.driveTo(0, 0, 0, 2, -0.5, out);
        assertTrue(out.omegaRadPerSec < 0);
    }

    @Test
    void sharpArcsSlowDownToRespectTheTurnRateLimit() {
        follower.driveTo(0, 0, 0, 0.1, 0.07, out); // alpha = 0.61 rad, distance 0.122 m
        assertEquals(0.5, out.omegaRadPerSec, 1e-12);
        assertTrue(out.vxMps < 0.1 && out.vxMps > 0);
    }

    @Test
    void largeHeadingErrorTurnsInPlace() {
        follower.driveTo(0, 0, 0, -1, 0.1, out); // behind, slightly left
        assertEquals(0.0, out.vxMps);
        assertEquals(0.5, out.omegaRadPerSec, 1e-12);
        follower.driveTo(0, 0, Math.PI / 2, 1, -0.01, out); // 90 degrees to the right
        assertEquals(0.0, out.vxMps);
        assertEquals(-0.5, out.omegaRadPerSec, 1e-12);
    }

    @Test
    void followsTheLookaheadPointAfterTheNearestPathPoint() {
        double[] xs = {0, 0.1, 0.2, 0.3, 0.4, 0.4, 0.4};
        double[] ys = {0, 0, 0, 0, 0, 0.1, 0.2};
        // Robot at the path's start heading +x: lookahead 0.3 m selects (0.3, 0): straight on.
        follower.follow(0, 0, 0, xs, ys, xs.length, out);
        assertEquals(0.1, out.vxMps, 1e-12);
        assertEquals(0.0, out.omegaRadPerSec, 1e-12);
        // Near the corner the target is the last point, up and to the left: turn left.
        follower.follow(0.35, 0, 0, xs, ys, xs.length, out);
        assertTrue(out.omegaRadPerSec > 0);
        assertTrue(Math.abs(out.omegaRadPerSec) <= 0.5 && Math.abs(out.vxMps) <= 0.1);
    }
}
