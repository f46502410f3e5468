package io.rtaware.sim.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.sim.map.OccupancyMap;
import io.rtaware.sim.map.RayCaster;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

class LaserTest {

    static final OccupancyMap ROOM = WorldTest.ROOM;
    static final double CELL = 0.02;
    static final LaserConfig EXACT = LaserConfig.URG_04LX.withNoise(0.0);

    private static LaserScan scan(LaserConfig cfg, Pose2d p, long seed) {
        LaserScan s = new LaserScan(cfg.beams());
        new Laser(cfg, new RayCaster(ROOM)).scan(p.xM(), p.yM(), p.yawRad(), 1.5, new SplittableRandom(seed), s);
        return s;
    }

    private static int beamAt(LaserScan s, double bearingRad) {
        return (int) Math.round((bearingRad - s.minAngleRad) / s.angleIncrementRad());
    }

    @Test
    void fieldOfViewAndBeamAngles() {
        LaserScan s = scan(EXACT, new Pose2d(2, 1.5, 0), 1);
        assertEquals(683, s.count());
        double inc = Math.toRadians(0.3515625);
        assertEquals(inc, s.angleIncrementRad(), 1e-12);
        assertEquals(-341 * inc, s.minAngleRad, 1e-12);
        assertEquals(341 * inc, s.maxAngleRad, 1e-12);
        assertEquals(Math.toRadians(240), s.maxAngleRad - s.minAngleRad, Math.toRadians(0.3));
        assertEquals(0.0, s.bearingRad(341), 1e-12);
        assertEquals(5.6, s.maxRangeM, "SCIP 2.0's DMAX:5600");
        assertEquals(1.5, s.serverTimeS);
    }

    @Test
    void rangesMatchAnalyticDistances() {
        // at (4.0, 1.5) facing +x: nothing before the east wall (box starts at y 2.3, pillar y <= 1.0),
        // which at x 9.6 is exactly the 5.6 m range away
        LaserScan s = scan(EXACT, new Pose2d(4.0, 1.5, 0.0), 1);
        assertEquals(5.6f, s.rangesM[beamAt(s, 0.0)]);
        // right (-90 deg): south wall at y = 0
        assertEquals(1.5, s.rangesM[beamAt(s, -Math.PI / 2)], CELL);
        // left (+90 deg): box bottom face at y = 2.3
        assertEquals(0.8, s.rangesM[beamAt(s, Math.PI / 2)], CELL);
        // at (8.0, 3.1) facing west: box east face at x = 6.0
        s = scan(EXACT, new Pose2d(8.0, 3.1, Math.PI), 1);
        assertEquals(2.0, s.rangesM[beamAt(s, 0.0)], CELL);
        // facing +x: east wall at 9.6; and a 30 deg beam to the wall: 1.6 / cos 30
        s = scan(EXACT, new Pose2d(8.0, 3.1, 0.0), 1);
        assertEquals(1.6, s.rangesM[beamAt(s, 0.0)], CELL);
        double b = s.bearingRad(beamAt(s, Math.toRadians(30)));
        assertEquals(1.6 / Math.cos(b), s.rangesM[beamAt(s, b)], CELL);
        // pillar at (5.0, 0.8), west face x = 4.8, from (3.5, 0.8)
        s = scan(EXACT, new Pose2d(3.5, 0.8, 0.0), 1);
        assertEquals(1.3, s.rangesM[beamAt(s, 0.0)], CELL);
        // corner view: every beam is at most the max range and at least the robot radius
        for (int i = 0; i < s.count(); i++) {
            assertTrue(s.rangesM[i] <= 5.6f && s.rangesM[i] >= 0.2f);
        }
    }

    @Test
    void beamsMatchBruteForceMarching() {
        RayCaster caster = new RayCaster(ROOM);
        SplittableRandom r = new SplittableRandom(3);
        for (int k = 0; k < 2000; k++) {
            double x = 0.2 + r.nextDouble() * 9.2;
            double y = 0.2 + r.nextDouble() * 5.8;
            if (ROOM.isObstacleAt(x, y)) {
                continue;
            }
            double a = r.nextDouble() * 2 * Math.PI;
            double dx = Math.cos(a);
            double dy = Math.sin(a);
            double fast = caster.castM(x, y, dx, dy, 4.0);
            double t = 0;
            while (t < 4.0 && !ROOM.isObstacleAt(x + dx * t, y + dy * t)) {
                t += 0.0005;
            }
            assertEquals(Math.min(t, 4.0), fast, 0.001, "ray " + k);
        }
    }

    @Test
    void noiseStatisticsWithFixedSeed() {
        LaserConfig noisy = LaserConfig.URG_04LX.withNoise(0.01);
        Pose2d p = new Pose2d(8.0, 3.1, 0.0);
        LaserScan exact = scan(EXACT, p, 1);
        double sum = 0;
        double sumSq = 0;
        int n = 0;
        for (int seed = 0; seed < 30; seed++) {
            LaserScan s = scan(noisy, p, seed);
            for (int i = 0; i < s.count(); i++) {
                if (exact.rangesM[i] < 4.0f) {
                    double e = s.rangesM[i] - exact.rangesM[i];
                    sum += e;
                    sumSq += e * e;
                    n++;
                }
            }
        }
        double mean = sum / n;
        double sd = Math.sqrt(sumSq / n - mean * mean);
        assertTrue(n > 10000);
        assertEquals(0.0, mean, 0.0005);
        assertEquals(0.01, sd, 0.0005);
        LaserScan a = scan(noisy, p, 9);
        LaserScan b = scan(noisy, p, 9);
        for (int i = 0; i < a.count(); i++) {
            assertEquals(Float.floatToRawIntBits(a.rangesM[i]), Float.floatToRawIntBits(b.rangesM[i]));
        }
    }
}
