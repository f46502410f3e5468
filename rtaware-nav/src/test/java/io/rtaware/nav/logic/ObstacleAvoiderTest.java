package io.rtaware.nav.logic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.MotionRequest;
import org.junit.jupiter.api.Test;

class ObstacleAvoiderTest {

    private final ObstacleAvoider avoider = new ObstacleAvoider(0.4, 0.6, 0.25, 0.03, 0.5);
    private final MotionRequest out = new MotionRequest();

    /** 181 beams, one per degree from -90 to +90, all at 5 m (nothing near). */
    private static LaserScan openScan() {
        LaserScan s = new LaserScan(181);
        s.setCount(181);
        s.minAngleRad = -Math.PI / 2;
        s.maxAngleRad = Math.PI / 2;
        s.maxRangeM = 5.6;
        for (int i = 0; i < 181; i++) {
            s.rangesM[i] = 5f;
        }
        return s;
    }

    private static void obstacle(LaserScan s, int degrees, float rangeM) {
        s.rangesM[degrees + 90] = rangeM;
    }

    @Test
    void nothingInTheZoneRequestsNothing() {
        assertFalse(avoider.decide(openScan(), out));
        assertFalse(out.active);
        assertEquals(0.0, out.vxMps);
    }

    @Test
    void obstacleAheadLeftSlowsAndTurnsRight() {
        LaserScan s = openScan();
        obstacle(s, 20, 0.35f);
        assertTrue(avoider.decide(s, out));
        assertTrue(out.active);
        assertEquals(0.03, out.vxMps);
        assertEquals(-0.5, out.omegaRadPerSec);
    }

    @Test
    void obstacleAheadRightSlowsAndTurnsLeft() {
        LaserScan s = openScan();
        obstacle(s, -20, 0.35f);
        obstacle(s, 10, 0.38f);
        assertTrue(avoider.decide(s, out));
        assertEquals(0.5, out.omegaRadPerSec, "the right one is nearer");
    }

    @Test
    void veryNearObstacleStopsForwardMotion() {
        LaserScan s = openScan();
        obstacle(s, 5, 0.2f);
        assertTrue(avoider.decide(s, out));
        assertEquals(0.0, out.vxMps);
        assertEquals(-0.5, out.omegaRadPerSec);
    }

    @Test
    void deadAheadTurnsTowardTheMoreOpenSide() {
        LaserScan s = openScan();
        obstacle(s, 0, 0.3f);
        for (int d = 30; d <= 90; d++) {
            obstacle(s, d, 1.0f); // left side mostly closed
        }
        assertTrue(avoider.decide(s, out));
        assertEquals(-0.5, out.omegaRadPerSec);
    }

    @Test
    void obstaclesBeyondTheZoneAreIgnored() {
        LaserScan s = openScan();
        obstacle(s, 10, 0.45f); // too far
        obstacle(s, 60, 0.1f); // outside the sector (0.6 rad = 34 degrees)
        obstacle(s, -80, 0.1f);
        obstacle(s, 0, 5.6f); // max range: no return
        obstacle(s, 1, Float.POSITIVE_INFINITY); // no return within range (REP 117)
        obstacle(s, 2, Float.NaN); // no reading
        assertFalse(avoider.decide(s, out));
        assertFalse(out.active);
    }

    @Test
    void aSensorThatSeesEverythingTooCloseToMeasureStopsTheRobot() {
        for (float tooClose : new float[] {Float.NEGATIVE_INFINITY, 0f, 0.01f}) {
            LaserScan s = openScan();
            s.minRangeM = 0.02;
            for (int i = 0; i < s.count(); i++) {
                s.rangesM[i] = tooClose;
            }
            assertTrue(avoider.decide(s, out), "a blinded laser (" + tooClose + ") is an obstacle, not free space");
            assertEquals(0.0, out.vxMps, "an obstacle at the 0.02 m minimum range is inside the 0.25 m stop range");
            assertTrue(out.omegaRadPerSec != 0, "and the robot turns away");
        }
    }

    @Test
    void aReadingOfZeroIsAnObstacleAtZeroWhenTheSensorDeclaresNoMinimum() {
        LaserScan s = openScan();
        obstacle(s, 5, 0f);
        assertTrue(avoider.decide(s, out));
        assertEquals(0.0, out.vxMps);
        assertEquals(-0.5, out.omegaRadPerSec, "left of the heading: turn right");
    }

    @Test
    void badParametersAreRejectedByName() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new ObstacleAvoider(-1, 0.6, 0.2, 0.03, 0.5));
        assertTrue(e.getMessage().contains("safetyRangeM"));
        assertTrue(e.getMessage().contains("-1"));
    }
}
