package io.rtaware.robot.validate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.Odometry;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class SampleChecksTest {

    private static final SampleLimits LIMITS = SampleLimits.defaults();

    private static Odometry odometry() {
        Odometry o = new Odometry();
        o.xM = 1.5;
        o.yM = -2.0;
        o.yawRad = 3.0;
        o.vxMps = 0.1;
        o.omegaRadPerSec = -0.5;
        o.serverTimeS = 12.5;
        return o;
    }

    private static LaserScan scan() {
        LaserScan s = new LaserScan(8);
        s.setCount(5);
        s.minAngleRad = -Math.PI / 2;
        s.maxAngleRad = Math.PI / 2;
        s.maxRangeM = 8.0;
        s.serverTimeS = 3.0;
        for (int i = 0; i < 5; i++) {
            s.rangesM[i] = 1.0f + i;
        }
        s.rangesM[4] = 8.0f; // nothing hit: the maximum itself
        return s;
    }

    @Test
    void plausibleSamplesPass() {
        assertNull(SampleChecks.odometry(odometry(), Double.NaN, LIMITS));
        assertNull(SampleChecks.odometry(odometry(), 12.5, LIMITS), "an equal timestamp is allowed");
        assertNull(SampleChecks.scan(scan(), Double.NaN, LIMITS));
    }

    @ParameterizedTest
    @ValueSource(doubles = {Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, 1e9})
    void impossiblePosesAreNamed(double bad) {
        Odometry o = odometry();
        o.xM = bad;
        String reason = SampleChecks.odometry(o, Double.NaN, LIMITS);
        assertNotNull(reason);
        assertTrue(reason.contains(Double.toString(bad)) || reason.contains("(" + bad), reason);
    }

    @Test
    void impossibleVelocitiesYawAndTimes() {
        Odometry o = odometry();
        o.vxMps = 300;
        assertTrue(SampleChecks.odometry(o, Double.NaN, LIMITS).startsWith("speed = 300"));
        o = odometry();
        o.omegaRadPerSec = Double.NaN;
        assertEquals("turn rate = NaN", SampleChecks.odometry(o, Double.NaN, LIMITS));
        o = odometry();
        o.yawRad = 1e6;
        assertTrue(SampleChecks.odometry(o, Double.NaN, LIMITS).startsWith("yaw = 1000000.0"));
        o = odometry();
        assertTrue(SampleChecks.odometry(o, 13.0, LIMITS).contains("earlier than the previous"));
        o.serverTimeS = Double.NaN;
        assertEquals("timestamp = NaN", SampleChecks.odometry(o, Double.NaN, LIMITS));
        o.serverTimeS = -1;
        assertTrue(SampleChecks.odometry(o, Double.NaN, LIMITS).contains("negative"));
    }

    @Test
    void readingsCloserThanTheSensorCanMeasureAreObstaclesAtTheMinimumRange() {
        LaserScan s = scan();
        s.minRangeM = 0.02;
        s.rangesM[0] = Float.NEGATIVE_INFINITY; // REP 117: too close to measure
        s.rangesM[1] = 0f;                       // a Player laser's "nothing measurable"
        s.rangesM[2] = -0.5f;                    // below the minimum, whatever it means: not free space
        s.rangesM[3] = Float.POSITIVE_INFINITY;  // REP 117: no return within range
        assertEquals(0, SampleChecks.normalizeBeams(s, LIMITS), "none of these is dropped");
        assertEquals(0.02f, s.rangesM[0], "-Inf is an obstacle at the minimum range");
        assertEquals(0.02f, s.rangesM[1], "0 m is an obstacle at the minimum range");
        assertEquals(0.02f, s.rangesM[2], "a negative reading is an obstacle at the minimum range");
        assertEquals(8.0f, s.rangesM[3], "+Inf is nothing hit: the maximum range");
        assertNull(SampleChecks.scan(s, Double.NaN, LIMITS));
    }

    @ParameterizedTest
    @ValueSource(floats = {Float.NaN, 8.1f, 1e9f})
    void aReadingThatSaysNothingIsDroppedAndCountedNotTheScan(float bad) {
        LaserScan s = scan();
        s.rangesM[2] = bad;
        SampleValidator v = new SampleValidator("laser:0", LIMITS);
        assertTrue(v.acceptScan(s), "the scan is kept: " + v.lastRejection());
        assertTrue(Float.isNaN(s.rangesM[2]), "the beam says nothing now: " + s.rangesM[2]);
        assertEquals(1, v.droppedBeams());
        assertEquals(0, v.rejected());
        assertEquals(2.0f, s.rangesM[1], "the other beams are untouched");
    }

    @Test
    void aScanWithoutUsableBeamsIsImpossible() {
        LaserScan s = scan();
        for (int i = 0; i < s.count(); i++) {
            s.rangesM[i] = i % 2 == 0 ? Float.NaN : 50f;
        }
        SampleValidator v = new SampleValidator("laser:0", LIMITS);
        assertFalse(v.acceptScan(s));
        assertEquals("none of the 5 beams is a reading within [0.0, 8.0] m (or an infinity)", v.lastRejection());
        assertEquals(5, v.droppedBeams());
    }

    @Test
    void aScanWithNoBeamsOrFewerThanItsAnglesImplyIsImpossible() {
        LaserScan s = scan();
        s.setCount(0);
        assertEquals("the scan has no beams", SampleChecks.scan(s, Double.NaN, LIMITS));
        s = scan();
        s.impliedBeams = 181;
        assertEquals("the scan has 5 beams where its angles [-1.5707963267948966, 1.5707963267948966] rad imply 181",
                SampleChecks.scan(s, Double.NaN, LIMITS));
        s.impliedBeams = 6;
        assertNull(SampleChecks.scan(s, Double.NaN, LIMITS), "one beam of slack for drivers that count the ends apart");
    }

    @Test
    void aMinimumRangeNotBelowTheMaximumIsImpossible() {
        LaserScan s = scan();
        s.minRangeM = 8.0;
        assertEquals("min range = 8.0 m is outside [0, 8.0) m", SampleChecks.scan(s, Double.NaN, LIMITS));
        s.minRangeM = Double.NaN;
        assertEquals("min range = NaN m is outside [0, 8.0) m", SampleChecks.scan(s, Double.NaN, LIMITS));
    }

    @Test
    void aReadingWithinTheToleranceAboveTheMaximumPasses() {
        LaserScan s = scan();
        s.rangesM[0] = 8.05f;
        assertNull(SampleChecks.scan(s, Double.NaN, LIMITS));
    }

    @Test
    void impossibleScanGeometry() {
        assertNotNull(SampleChecks.scanGeometry(1.0, -1.0, 8, LIMITS));
        assertNotNull(SampleChecks.scanGeometry(-4, 4, 8, LIMITS));
        assertNotNull(SampleChecks.scanGeometry(-1, 1, 0, LIMITS));
        assertNotNull(SampleChecks.scanGeometry(-1, 1, Double.NaN, LIMITS));
        assertNotNull(SampleChecks.scanGeometry(-1, 1, 1e7, LIMITS));
        assertNull(SampleChecks.scanGeometry(-Math.PI, Math.PI, 30, LIMITS));
    }

    @Test
    void limitsAreThemselvesChecked() {
        assertThrows(IllegalArgumentException.class, () -> new SampleLimits(Double.NaN, 1, 1, 1, 1, 0));
        assertThrows(IllegalArgumentException.class, () -> new SampleLimits(1, 1, 1, 1, 1, -0.1));
    }

    @Test
    void validatorCountsAndForgetsTimeOnRestart() {
        SampleValidator v = new SampleValidator("position2d:0", LIMITS);
        Odometry o = odometry();
        assertTrue(v.acceptOdometry(o));
        o.serverTimeS = 10.0;
        assertFalse(v.acceptOdometry(o), "time went backwards");
        assertTrue(v.lastRejected());
        assertTrue(v.lastRejection().contains("earlier"));
        v.restart();
        assertFalse(v.lastRejected());
        assertTrue(v.acceptOdometry(o), "a new connection may start its clock again");
        assertEquals(2, v.accepted());
        assertEquals(1, v.rejected());
    }

    @Test
    void watchFaultsOnlyAfterAFullSpanOfRejectionsInWorldTime() {
        RejectionWatch w = new RejectionWatch(1_000_000_000L);
        assertFalse(w.observe(0, false));
        assertFalse(w.observe(100_000_000L, true));
        assertFalse(w.observe(1_099_999_999L, true));
        assertTrue(w.observe(1_100_000_000L, true));
        assertFalse(w.observe(1_200_000_000L, false), "a good sample ends the streak");
        assertFalse(w.observe(2_000_000_000L, true));
        assertEquals(2_000_000_000L, w.rejectingSinceNs());
        assertThrows(IllegalArgumentException.class, () -> new RejectionWatch(0));
    }
}
