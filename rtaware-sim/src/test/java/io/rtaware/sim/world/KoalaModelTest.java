package io.rtaware.sim.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.robot.geometry.Angles;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.sim.map.OccupancyMap;
import java.util.Arrays;
import org.apache.commons.math3.distribution.UniformRealDistribution;
import org.apache.commons.math3.stat.descriptive.DescriptiveStatistics;
import org.apache.commons.math3.stat.inference.KolmogorovSmirnovTest;
import org.junit.jupiter.api.Test;

/**
 * The Koala model measured on the world's own stepped time (no threads, no wall clock):
 * odometry drift statistics over fixed seeds match the configured error model; acceleration,
 * deceleration and command latency are exact; the laser's sweep and delivery are on time.
 */
class KoalaModelTest {

    private static final long MS = 1_000_000L;
    private static final int RUNS = 400;
    /** An empty 20 m x 20 m room: nothing to bump into. */
    private static final OccupancyMap EMPTY = emptyMap();

    private static OccupancyMap emptyMap() {
        OccupancyMap.CellState[] cells = new OccupancyMap.CellState[200 * 200];
        Arrays.fill(cells, OccupancyMap.CellState.FREE);
        return new OccupancyMap("empty", 200, 200, 0.1, -10, -10, cells);
    }

    private static RobotModel koalaWith(OdometryError error) {
        RobotModel k = RobotModel.koala(0.1);
        return new RobotModel(k.name(), k.body(), k.maxDecelMps2(), k.commandLatencyNs(), error, k.laserTiming(),
                k.topSpeedMps());
    }

    private static World world(RobotModel model, long seed) {
        return new World(EMPTY, new Pose2d(0, 0, 0), model, LaserConfig.URG_04LX, seed);
    }

    /** Drives until the true pose has moved {@code metres} straight ahead, then stops. */
    private static void driveStraight(World w, double metres) {
        w.command(0.1, 0);
        while (w.xM() < metres) {
            w.step(10 * MS);
        }
        w.command(0, 0);
        for (int i = 0; i < 50; i++) {
            w.step(10 * MS);
        }
    }

    /** Turns in place until the true heading has turned {@code rad} (at most pi). */
    private static double turnInPlace(World w, double rad) {
        w.command(0, 0.5);
        double turned = 0;
        double last = w.yawRad();
        while (turned < rad) {
            w.step(10 * MS);
            turned += Angles.normalize(w.yawRad() - last);
            last = w.yawRad();
        }
        w.command(0, 0);
        for (int i = 0; i < 50; i++) {
            w.step(10 * MS);
            turned += Angles.normalize(w.yawRad() - last);
            last = w.yawRad();
        }
        return turned;
    }

    @Test
    void distanceScaleErrorsAreUniformPerRunWithinTheConfiguredBound() {
        double bound = 0.03;
        double[] errors = new double[RUNS];
        for (int seed = 0; seed < RUNS; seed++) {
            World w = world(koalaWith(new OdometryError(bound, 0, 0, 0, 0)), seed);
            driveStraight(w, 1.0);
            errors[seed] = w.odometryPose().xM() / w.xM() - 1;
            assertTrue(Math.abs(errors[seed]) <= bound + 1e-12, "within the bound: " + errors[seed]);
        }
        DescriptiveStatistics s = new DescriptiveStatistics(errors);
        assertEquals(0.0, s.getMean(), 3 * bound / Math.sqrt(3 * RUNS), "mean of a uniform [-e, e]");
        assertEquals(bound / Math.sqrt(3), s.getStandardDeviation(), 0.1 * bound / Math.sqrt(3), "sd e/sqrt(3)");
        double p = new KolmogorovSmirnovTest().kolmogorovSmirnovTest(new UniformRealDistribution(-bound, bound), errors);
        assertTrue(p > 0.01, "uniform on [-e, e] (Kolmogorov-Smirnov p = " + p + ")");
    }

    @Test
    void rotationScaleErrorsAreUniformPerRunWithinTheConfiguredBound() {
        double bound = 0.08;
        double[] errors = new double[RUNS];
        for (int seed = 0; seed < RUNS; seed++) {
            World w = world(koalaWith(new OdometryError(0, bound, 0, 0, 0)), seed);
            double turned = turnInPlace(w, Math.PI / 2);
            errors[seed] = Angles.normalize(w.odometryPose().yawRad()) / turned - 1;
            assertEquals(0.0, w.odometryPose().xM(), 1e-12, "turning in place moves no odometry");
        }
        DescriptiveStatistics s = new DescriptiveStatistics(errors);
        assertTrue(s.getMax() <= bound + 1e-9 && s.getMin() >= -bound - 1e-9, "within the bound");
        assertEquals(bound / Math.sqrt(3), s.getStandardDeviation(), 0.1 * bound / Math.sqrt(3), "sd e/sqrt(3)");
        double p = new KolmogorovSmirnovTest().kolmogorovSmirnovTest(new UniformRealDistribution(-bound, bound), errors);
        assertTrue(p > 0.01, "uniform on [-e, e] (Kolmogorov-Smirnov p = " + p + ")");
    }

    @Test
    void distanceNoiseIsARandomWalkWithTheConfiguredSpread() {
        double sigma = 0.01;
        double[] errors = new double[RUNS];
        for (int seed = 0; seed < RUNS; seed++) {
            World w = world(koalaWith(new OdometryError(0, 0, 0, sigma, 0)), seed);
            driveStraight(w, 1.0);
            errors[seed] = w.odometryPose().xM() - w.xM();
        }
        DescriptiveStatistics s = new DescriptiveStatistics(errors);
        double expectedSd = sigma * Math.sqrt(1.0); // the true distance is 1 m (plus at most one step)
        assertEquals(0.0, s.getMean(), 3 * expectedSd / Math.sqrt(RUNS), "zero mean");
        assertEquals(expectedSd, s.getStandardDeviation(), 0.1 * expectedSd, "sd sigma * sqrt(distance)");
    }

    @Test
    void headingDriftBendsAStraightLineByTheDrawnRate() {
        World w = world(koalaWith(new OdometryError(0, 0, 0.01, 0, 0)), 7L);
        driveStraight(w, 2.0);
        double yawPerM = w.odometryPose().yawRad() / w.xM();
        assertTrue(Math.abs(yawPerM) <= 0.01 + 1e-12 && yawPerM != 0, "drift within +-0.01 rad/m: " + yawPerM);
        assertEquals(0.0, w.yawRad(), 0.0, "the true heading did not change");
    }

    @Test
    void theKoalaDriftsMoreInRotationThanInDistance() {
        DescriptiveStatistics distance = new DescriptiveStatistics();
        DescriptiveStatistics rotation = new DescriptiveStatistics();
        for (int seed = 0; seed < 100; seed++) {
            World a = world(RobotModel.koala(0.1), seed);
            driveStraight(a, 1.0);
            distance.addValue(Math.abs(a.odometryPose().xM() / a.xM() - 1));
            World b = world(RobotModel.koala(0.1), seed);
            double turned = turnInPlace(b, 1.0);
            rotation.addValue(Math.abs(b.odometryPose().yawRad() / turned - 1));
        }
        assertTrue(rotation.getMean() > 2 * distance.getMean(),
                "relative rotation error " + rotation.getMean() + " vs distance " + distance.getMean());
    }

    @Test
    void sameSeedSameDrift() {
        World a = world(RobotModel.koala(0.1), 3L);
        World b = world(RobotModel.koala(0.1), 3L);
        driveStraight(a, 1.0);
        driveStraight(b, 1.0);
        assertEquals(a.odometryPose(), b.odometryPose());
    }

    @Test
    void commandReachesTheWheelsAfterTheLatencyThenAcceleratesAtTheLimit() {
        RobotModel koala = RobotModel.koala(0.1);
        assertEquals(30 * MS, koala.commandLatencyNs());
        World w = world(koala, 1L);
        w.command(0.1, 0);
        for (int i = 0; i < 30; i++) {
            w.step(MS);
            assertEquals(0.0, w.speedMps(), 0.0, "still at rest at " + (i + 1) + " ms");
        }
        // due at 30 ms: the sub-step starting at 30 ms accelerates at 0.5 m/s^2
        w.step(MS);
        assertEquals(0.5 * 0.001, w.speedMps(), 1e-15);
        for (int i = 0; i < 199; i++) {
            w.step(MS);
        }
        assertEquals(0.1, w.speedMps(), 1e-12, "0.1 m/s after 200 ms at 0.5 m/s^2");
    }

    @Test
    void stopCommandBrakesAtTheDecelerationLimitAfterTheLatency() {
        World w = world(RobotModel.koala(0.1), 1L);
        w.command(0.1, 0);
        for (int i = 0; i < 1000; i++) {
            w.step(MS);
        }
        assertEquals(0.1, w.speedMps(), 1e-12);
        double x0 = w.xM();
        w.command(0, 0);
        for (int i = 0; i < 30; i++) {
            w.step(MS);
        }
        assertEquals(0.1, w.speedMps(), 1e-12, "full speed during the latency");
        w.step(MS);
        assertEquals(0.1 - 1.0 * 0.001, w.speedMps(), 1e-12, "1.0 m/s^2 braking");
        for (int i = 0; i < 99; i++) {
            w.step(MS);
        }
        assertEquals(0.0, w.speedMps(), 1e-12, "stopped 100 ms after the latency");
        assertEquals(RobotModel.koala(0.1).stoppingDistanceM(0.1), w.xM() - x0, 2e-4,
                "the model's stopping distance: 3 mm of latency plus 5 mm of braking");
    }

    @Test
    void idealModelActsAtOnceWithoutLatency() {
        World w = world(RobotModel.ideal(0.1), 1L);
        w.command(0.1, 0);
        w.step(MS);
        assertEquals(0.5 * 0.001, w.speedMps(), 1e-15);
        assertEquals(w.pose(), w.odometryPose());
    }

    @Test
    void anInstantScansFirstBeamIsTheScansOwnTime() {
        World w = world(RobotModel.ideal(0.1), 1L);
        long periodNs = LaserConfig.URG_04LX.periodNs();
        for (long t = 0; t < periodNs + 5 * MS; t += MS) {
            w.step(MS);
        }
        assertEquals(periodNs, w.scanFirstBeamNs(), "the scan taken at the first period, every beam at once");
        assertEquals(periodNs * 1e-9, w.scan().serverTimeS, 1e-12, "and stamped then");
    }

    @Test
    void urgScanIsSweptOverTheTurnAndDeliveredTenMillisecondsAfterItsLastBeam() {
        World w = world(RobotModel.koala(0.1), 1L);
        assertTrue(w.scanFresh(), "a scan at time zero");
        double beamNs = 100e6 * LaserConfig.URG_04LX.angleIncrementRad() / (2 * Math.PI); // 97.66 us
        long deliveryNs = (long) (682 * beamNs) + 10 * MS; // 66.6 ms + 10 ms
        long firstFresh = -1;
        long secondFresh = -1;
        for (long t = MS; t <= 200 * MS; t += MS) {
            w.step(MS);
            if (w.scanFresh()) {
                if (firstFresh < 0) {
                    firstFresh = t;
                    assertEquals(t * 1e-9, w.scan().serverTimeS, 1e-12, "stamped at delivery");
                    assertEquals(0L, w.scanFirstBeamNs(), "the first sweep's first beam at time zero");
                } else if (secondFresh < 0) {
                    secondFresh = t;
                    assertEquals(100 * MS, w.scanFirstBeamNs(), "the second sweep starts on the 100 ms turn grid");
                }
            }
        }
        assertEquals((deliveryNs / MS + 1) * MS, firstFresh, "first step at or after the delivery time");
        assertEquals(firstFresh + 100 * MS, secondFresh, "one scan per 100 ms turn");
        assertFalse(Double.isNaN(w.scan().rangesM[0]));
    }

    @Test
    void eachBeamIsMeasuredFromWhereTheRobotIsWhenTheMirrorPassesIt() {
        // The paper room's west wall is at x = 0 (inner face); the robot backs away from it
        // facing west at 0.1 m/s, so a later beam sees the wall further away.
        OccupancyMap room = io.rtaware.sim.scenario.ScenarioLoader.load("paper-room").map().orElseThrow();
        RobotModel koala = RobotModel.koala(0.1);
        World w = new World(room, new Pose2d(1.0, 3.1, Math.PI), koala, LaserConfig.URG_04LX, 1L);
        w.command(-0.1, 0);
        for (int i = 0; i < 1000; i++) {
            w.step(MS); // at full speed backwards after 1 s
        }
        int fresh = 0;
        while (fresh < 2) {
            w.step(MS);
            if (w.scanFresh()) {
                fresh++;
            }
        }
        int mid = LaserConfig.URG_04LX.beams() / 2;
        double rMid = w.scan().rangesM[mid];
        // The middle beam was measured about 33 ms after the first and 43 ms before delivery.
        double xAtDelivery = w.xM();
        assertTrue(rMid < xAtDelivery - 0.002, "measured before delivery, nearer the wall: " + rMid + " vs " + xAtDelivery);
        assertTrue(rMid > xAtDelivery - 0.02, "but within this scan's 77 ms: " + rMid + " vs " + xAtDelivery);
    }
}
