package io.rtaware.sim.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.sim.map.OccupancyMap;
import java.util.Arrays;
import org.junit.jupiter.api.Test;

/**
 * One robot, many runs: the systematic odometry errors come from the robot seed alone, the
 * noise from the run's seed, measured on the world's stepped time.
 */
class RobotSeedTest {

    private static final long MS = 1_000_000L;

    private static OccupancyMap empty() {
        OccupancyMap.CellState[] cells = new OccupancyMap.CellState[200 * 200];
        Arrays.fill(cells, OccupancyMap.CellState.FREE);
        return new OccupancyMap("empty", 200, 200, 0.1, -10, -10, cells);
    }

    private static World drive(long runSeed, long robotSeed) {
        World w = new World(empty(), new Pose2d(0, 0, 0), RobotModel.koala(0.1), LaserConfig.URG_04LX, runSeed, robotSeed);
        w.command(0.1, 0.05);
        for (int i = 0; i < 2000; i++) {
            w.step(10 * MS);
        }
        return w;
    }

    @Test
    void theSameRobotSeedGivesTheSameSystematicErrorsWhateverTheRun() {
        OdometryBias first = drive(1L, 5L).odometryBias();
        for (long run = 2; run <= 20; run++) {
            assertEquals(first, drive(run, 5L).odometryBias(), "robot seed 5 in run " + run);
        }
        assertEquals(first, OdometryBias.draw(OdometryError.KOALA, 5L), "drawn from the robot seed alone");
        assertNotEquals(first, drive(1L, 6L).odometryBias(), "another robot seed is another robot");
    }

    @Test
    void differentRunSeedsGiveDifferentNoiseOnTheSameRobot() {
        World a = drive(1L, 5L);
        World b = drive(2L, 5L);
        World again = drive(1L, 5L);
        assertEquals(a.pose(), b.pose(), "the true path does not depend on odometry noise");
        assertNotEquals(a.odometryPose(), b.odometryPose(), "each run's odometry noise differs");
        assertEquals(a.odometryPose(), again.odometryPose(), "the same run seed and robot seed repeat exactly");
    }

    @Test
    void systematicErrorsStayWithinTheirBounds() {
        for (long robot = 0; robot < 200; robot++) {
            OdometryBias bias = OdometryBias.draw(OdometryError.KOALA, robot);
            assertEquals(1.0, bias.distanceScale(), 0.03, "distance scale of robot " + robot);
            assertEquals(1.0, bias.rotationScale(), 0.08, "rotation scale of robot " + robot);
            assertEquals(0.0, bias.headingDriftRadPerM(), 0.01, "heading drift of robot " + robot);
        }
        assertEquals(OdometryBias.NONE, OdometryBias.draw(OdometryError.NONE, 3L), "no bounds, no errors");
    }
}
