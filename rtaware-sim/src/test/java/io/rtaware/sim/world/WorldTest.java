package io.rtaware.sim.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.sim.map.OccupancyMap;
import io.rtaware.sim.scenario.ScenarioLoader;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class WorldTest {

    static final OccupancyMap ROOM = ScenarioLoader.load("paper-room").map().orElseThrow();
    static final long MS = 1_000_000L;

    private static World world(Pose2d start) {
        return new World(ROOM, start, RobotConfig.KOALA, LaserConfig.URG_04LX, 42L);
    }

    private static void run(World w, double seconds, long stepNs) {
        long steps = Math.round(seconds * 1e9 / stepNs);
        for (long i = 0; i < steps; i++) {
            w.step(stepNs);
        }
    }

    @Test
    void drivesStraightAtTopSpeedAfterAccelerating() {
        World w = world(new Pose2d(1.0, 1.5, 0.0));
        w.command(0.5, 0.0); // clamped to 0.1 m/s
        run(w, 10.0, 10 * MS);
        // 0.2 s ramp at 0.5 m/s^2 loses 0.01 m against 10 s at 0.1 m/s
        assertEquals(1.0 + 1.0 - 0.01, w.xM(), 1e-3);
        assertEquals(1.5, w.yM(), 1e-12);
        assertEquals(0.1, w.speedMps(), 1e-12);
        assertFalse(w.stalled());
        assertEquals(10.0, w.timeS(), 1e-9);
    }

    @Test
    void turnsInPlace() {
        World w = world(new Pose2d(2.0, 1.5, 0.0));
        w.command(0.0, 0.5);
        run(w, 2.0, 10 * MS);
        // ramp 0.25 s at 2 rad/s^2 loses 0.0625 rad against 1 rad
        assertEquals(1.0 - 0.0625, w.yawRad(), 5e-3);
        assertEquals(2.0, w.xM(), 1e-12);
        assertEquals(1.5, w.yM(), 1e-12);
    }

    @Test
    void followsAnArc() {
        World w = new World(ROOM, new Pose2d(2.0, 1.5, 0.0),
                new RobotConfig(0.2, 0.1, 0.5, 1e6, 1e6, 16, 0, 0), LaserConfig.URG_04LX, 1L);
        w.command(0.1, 0.1); // radius 1 m around (2, 2.5)
        run(w, Math.PI / 0.1 / 2, MS); // a quarter circle
        assertEquals(3.0, w.xM(), 1e-3);
        assertEquals(2.5, w.yM(), 1e-3);
        assertEquals(Math.PI / 2, w.yawRad(), 1e-3);
        assertEquals(1.0, Math.hypot(w.xM() - 2.0, w.yM() - 2.5), 1e-6);
    }

    @Test
    void stopsAtWallWithStallAndCountsOneContact() {
        World w = world(new Pose2d(9.0, 3.0, 0.0));
        w.command(0.1, 0.0);
        run(w, 10.0, 10 * MS);
        assertEquals(9.6 - 0.2, w.xM(), 1e-4);
        assertTrue(w.xM() <= 9.4 + 1e-12, "never inside the wall");
        assertTrue(w.stalled());
        assertTrue(w.odometry().stall || !w.odometryFresh());
        assertEquals(1, w.contactCount());
        run(w, 5.0, 10 * MS); // keeps pushing: still one contact event
        assertEquals(1, w.contactCount());
        w.command(-0.1, 0.0);
        run(w, 2.0, 10 * MS);
        assertFalse(w.stalled());
        w.command(0.1, 0.0);
        run(w, 5.0, 10 * MS);
        assertEquals(2, w.contactCount());
    }

    @Test
    void doesNotTunnelWithCoarseSteps() {
        World w = new World(ROOM, new Pose2d(4.4, 0.8, 0.0), RobotConfig.KOALA, LaserConfig.URG_04LX, 1L);
        w.command(0.1, 0.0);
        for (int i = 0; i < 20; i++) {
            w.step(1_000 * MS); // 1 s steps = 0.1 m each, pillar face at 4.8
        }
        assertEquals(4.6, w.xM(), 1e-4);
        assertTrue(w.stalled());
        World big = new World(ROOM, new Pose2d(4.4, 0.8, 0.0), RobotConfig.KOALA, LaserConfig.URG_04LX, 1L);
        big.command(0.1, 0.0);
        big.step(60_000 * MS); // one minute in one step
        assertEquals(4.6, big.xM(), 1e-4);
        assertEquals(1, big.contactCount());
    }

    @Test
    void canLeaveAnObstacleItWasPlacedIn() {
        World w = world(new Pose2d(1.0, 1.0, 0.0));
        w.setPose(new Pose2d(0.1, 3.0, 0.0)); // overlaps the west wall
        w.command(0.1, 0.0);
        run(w, 3.0, 10 * MS);
        assertTrue(w.xM() > 0.3, "drove out: " + w.xM());
        w.setPose(new Pose2d(0.1, 3.0, Math.PI));
        run(w, 1.0, 10 * MS);
        assertEquals(0.1, w.xM(), 1e-12);
    }

    @Test
    void motorsOffStopsTheRobot() {
        World w = world(new Pose2d(1.0, 1.5, 0.0));
        w.command(0.1, 0.0);
        run(w, 1.0, 10 * MS);
        w.setMotorsEnabled(false);
        run(w, 1.0, 10 * MS);
        assertEquals(0.0, w.speedMps());
    }

    @Test
    void publishesOdometryAt16HzAndScansAt10Hz() {
        World w = world(new Pose2d(1.0, 1.5, 0.0));
        assertTrue(w.odometryFresh());
        assertTrue(w.scanFresh());
        int odo = 0;
        int scans = 0;
        for (int i = 0; i < 1000; i++) { // 10 s in 10 ms steps
            w.step(10 * MS);
            odo += w.odometryFresh() ? 1 : 0;
            scans += w.scanFresh() ? 1 : 0;
        }
        assertEquals(160, odo);
        assertEquals(100, scans);
        assertEquals(10.0, w.odometry().serverTimeS, 0.07);
        assertEquals(10.0, w.scan().serverTimeS, 1e-9);
    }

    @Test
    void sameSeedSameTrajectoryBitForBit() {
        RobotConfig noisy = RobotConfig.KOALA.withOdometryNoise(0.01, 0.01);
        List<double[]> a = trajectory(noisy, 7L);
        List<double[]> b = trajectory(noisy, 7L);
        assertEquals(a.size(), b.size());
        for (int i = 0; i < a.size(); i++) {
            for (int k = 0; k < a.get(i).length; k++) {
                assertEquals(Double.doubleToRawLongBits(a.get(i)[k]), Double.doubleToRawLongBits(b.get(i)[k]));
            }
        }
        List<double[]> c = trajectory(noisy, 8L);
        boolean differs = false;
        for (int i = 0; i < a.size(); i++) {
            differs |= a.get(i)[5] != c.get(i)[5];
        }
        assertTrue(differs, "a different seed gives different noise");
    }

    private static List<double[]> trajectory(RobotConfig cfg, long seed) {
        World w = new World(ROOM, new Pose2d(0.8, 0.8, 0.0), cfg, LaserConfig.URG_04LX, seed);
        List<double[]> out = new ArrayList<>();
        for (int i = 0; i < 3000; i++) {
            w.command(0.1, Math.sin(i * 0.01) * 0.5);
            w.step((7 + i % 5) * MS);
            out.add(new double[] {w.xM(), w.yM(), w.yawRad(), w.odometry().xM, w.odometry().yawRad,
                w.scan().rangesM[300]});
        }
        return out;
    }

    @Test
    void rejectsBadInput() {
        World w = world(new Pose2d(1.0, 1.5, 0.0));
        assertThrows(IllegalArgumentException.class, () -> w.step(-1));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new RobotConfig(-0.2, 0.1, 0.5, 1, 1, 16, 0, 0));
        assertTrue(e.getMessage().contains("radiusM") && e.getMessage().contains("-0.2"));
        e = assertThrows(IllegalArgumentException.class, () -> new LaserConfig(0, 0.01, 0.02, 4, 10, 0));
        assertTrue(e.getMessage().contains("beams") && e.getMessage().contains("0"));
    }
}
