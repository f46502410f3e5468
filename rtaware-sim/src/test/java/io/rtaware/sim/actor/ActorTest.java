package io.rtaware.sim.actor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.robot.geometry.Point2d;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.sim.map.OccupancyMap;
import io.rtaware.sim.world.LaserConfig;
import io.rtaware.sim.world.RobotModel;
import io.rtaware.sim.world.World;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Actors move exactly as specified on stepped time and are in the ground truth, the laser and collisions. */
class ActorTest {

    private static final long MS = 1_000_000L;
    private static final double EXACT = 1e-12;

    private static ActorSpec body(List<Point2d> path, double speed, ActorSpec.Repeat repeat, double startAtS) {
        return new ActorSpec("p", ActorSpec.Kind.BODY, new ActorShape.Circle(0.25), path, speed, repeat, startAtS, 0, 0, 0);
    }

    private static void at(Actors a, long tNs, double x, double y) {
        a.update(tNs, 100, 100);
        assertEquals(x, a.xM(0), EXACT, "x at " + tNs / 1e6 + " ms");
        assertEquals(y, a.yM(0), EXACT, "y at " + tNs / 1e6 + " ms");
    }

    @Test
    void aBodyWaitsForItsStartThenWalksItsPathOnceAndStops() {
        Actors a = new Actors(List.of(body(List.of(new Point2d(0, 0), new Point2d(2, 0), new Point2d(2, 1)), 0.5,
                ActorSpec.Repeat.ONCE, 1.0)), 1L);
        at(a, 0, 0, 0);
        at(a, 1000 * MS, 0, 0);
        assertFalse(a.started(0), "not yet moving at its start time");
        at(a, 1500 * MS, 0.25, 0);
        assertEquals(0.5, a.vxMps(0), EXACT);
        at(a, 5000 * MS, 2.0, 0);
        at(a, 6000 * MS, 2.0, 0.5);
        assertEquals(0.5, a.vyMps(0), EXACT);
        at(a, 7000 * MS, 2.0, 1.0);
        at(a, 60_000 * MS, 2.0, 1.0);
        assertEquals(0.0, a.vyMps(0), 0.0, "stopped at the end of a once path");
    }

    @Test
    void aBodyGoesBackAndForthOrRoundALoop() {
        Actors back = new Actors(List.of(body(List.of(new Point2d(0, 0), new Point2d(2, 0)), 1.0,
                ActorSpec.Repeat.BACK_AND_FORTH, 0)), 1L);
        at(back, 2500 * MS, 1.5, 0);
        assertEquals(-1.0, back.vxMps(0), EXACT, "walking back");
        at(back, 4250 * MS, 0.25, 0);
        assertEquals(1.0, back.vxMps(0), EXACT, "out again");
        Actors loop = new Actors(List.of(body(List.of(new Point2d(0, 0), new Point2d(3, 0), new Point2d(3, 4)), 1.0,
                ActorSpec.Repeat.LOOP, 0)), 1L);
        at(loop, 9500 * MS, 3 - 0.6 * 2.5, 4 - 0.8 * 2.5); // 12 m round: 7 m out, then 2.5 m of the 5 m way back
        at(loop, 13_000 * MS, 1, 0); // round once and 1 m on
    }

    @Test
    void aBodyStartsWhenTheRobotComesWithinItsDistance() {
        ActorSpec spec = new ActorSpec("p", ActorSpec.Kind.BODY, new ActorShape.Circle(0.25),
                List.of(new Point2d(5, 0), new Point2d(5, 2)), 1.0, ActorSpec.Repeat.ONCE, 0, 1.5, 0, 0);
        Actors a = new Actors(List.of(spec), 1L);
        a.update(1000 * MS, 3.0, 0);
        a.update(2000 * MS, 3.4, 0);
        assertFalse(a.started(0), "1.6 m away");
        a.update(3000 * MS, 3.5, 0);
        assertEquals(5.0, a.xM(0), EXACT);
        assertEquals(0.0, a.yM(0), EXACT, "starts now, has not moved yet");
        a.update(3500 * MS, 3.5, 0);
        assertEquals(0.5, a.yM(0), EXACT, "half a second after the robot came within 1.5 m");
    }

    @Test
    void aDoorClosesAndAnObstacleAppearsAtTheirTimes() {
        ActorSpec door = new ActorSpec("door", ActorSpec.Kind.DOOR, new ActorShape.Box(1.0, 0.2),
                List.of(new Point2d(2, 0)), 0, ActorSpec.Repeat.ONCE, 0, 0, 0, 20);
        ActorSpec box = new ActorSpec("box", ActorSpec.Kind.OBSTACLE, new ActorShape.Box(0.5, 0.5),
                List.of(new Point2d(0, 3)), 0, ActorSpec.Repeat.ONCE, 0, 0, 0, 60);
        Actors a = new Actors(List.of(door, box), 1L);
        a.update(19_999 * MS, 0, 0);
        assertFalse(a.present(0), "open before 20 s");
        assertEquals(Double.POSITIVE_INFINITY, a.clearanceM(2, 0.5));
        a.update(20_000 * MS, 0, 0);
        assertTrue(a.present(0), "closed at 20 s");
        assertEquals(0.4, a.clearanceM(2, 0.5), EXACT);
        assertEquals(1.5, a.castM(2, -1.6, 0, 1, 4.0), EXACT, "a beam up through the doorway hits the door's face");
        assertFalse(a.present(1));
        a.update(60_000 * MS, 0, 0);
        assertTrue(a.present(1), "the obstacle is there from 60 s");
        assertEquals(1.25, a.castM(0, 1.5, 0, 1, 4.0), EXACT, "a beam from 1.5 m below its centre hits its near face");
    }

    @Test
    void theStartJitterComesFromTheRunSeed() {
        ActorSpec spec = new ActorSpec("p", ActorSpec.Kind.BODY, new ActorShape.Circle(0.25),
                List.of(new Point2d(0, 0), new Point2d(10, 0)), 1.0, ActorSpec.Repeat.ONCE, 1.0, 0, 5.0, 0);
        double[] x = new double[3];
        for (int seed = 0; seed < 3; seed++) {
            Actors a = new Actors(List.of(spec), seed);
            a.update(7000 * MS, 100, 100);
            x[seed] = a.xM(0);
            Actors again = new Actors(List.of(spec), seed);
            again.update(7000 * MS, 100, 100);
            assertEquals(x[seed], again.xM(0), 0.0, "the same seed, the same start");
            assertTrue(x[seed] > 1.0 - EXACT && x[seed] <= 6.0, "started between 1 s and 6 s: " + x[seed]);
        }
        assertTrue(x[0] != x[1] || x[1] != x[2], "other seeds, other starts: " + Arrays.toString(x));
    }

    private static OccupancyMap empty() {
        OccupancyMap.CellState[] cells = new OccupancyMap.CellState[200 * 200];
        Arrays.fill(cells, OccupancyMap.CellState.FREE);
        return new OccupancyMap("empty", 200, 200, 0.05, -5, -5, cells);
    }

    @Test
    void theLaserSeesAPersonCrossingAndAPersonWalkingIntoTheRobotIsAContact() {
        ActorSpec person = new ActorSpec("p", ActorSpec.Kind.BODY, new ActorShape.Circle(0.25),
                List.of(new Point2d(2, -3), new Point2d(2, 3)), 1.0, ActorSpec.Repeat.ONCE, 0, 0, 0, 0);
        World w = new World(empty(), new Pose2d(0, 0, 0), RobotModel.ideal(0.1), LaserConfig.URG_04LX.withNoise(0), 1L, 1L,
                List.of(person));
        int ahead = LaserConfig.URG_04LX.beams() / 2;
        assertEquals(LaserConfig.URG_04LX.maxRangeM(), w.scan().rangesM[ahead], 1e-6,
                "nothing ahead at the start: the person is 3 m to the side");
        for (int i = 0; i < 300; i++) {
            w.step(10 * MS);
        }
        assertEquals(2.0, w.actors().xM(0), EXACT);
        assertEquals(0.0, w.actors().yM(0), 1e-9, "crossing the robot's line at 3 s");
        assertEquals(1.75, w.scan().rangesM[ahead], 1e-6, "the beam straight ahead hits the person's near side");
        assertEquals(0, w.contactCount());
        assertEquals(World.CLEARANCE_LIMIT_M, w.minClearanceM(), 0.0, "never nearer than the limit: 1.55 m at the closest");

        ActorSpec walker = new ActorSpec("w", ActorSpec.Kind.BODY, new ActorShape.Circle(0.25),
                List.of(new Point2d(0, -2), new Point2d(0, 2)), 0.5, ActorSpec.Repeat.ONCE, 0, 0, 0, 0);
        World standing = new World(empty(), new Pose2d(0, 0, 0), RobotModel.ideal(0.1), LaserConfig.URG_04LX, 1L, 1L,
                List.of(walker));
        for (int i = 0; i < 800; i++) {
            standing.step(10 * MS); // 8 s: the person walks through where the robot stands
        }
        assertEquals(1, standing.contactCount(), "the person walked into the standing robot: one contact");
        assertEquals(0.0, standing.minClearanceM(), 0.0);
        assertEquals(0, standing.nearMisses(), "an approach that touched is a collision, not a near miss");
    }

    @Test
    void anApproachWithinTheMarginThatDoesNotTouchIsANearMiss() {
        // passes 0.48 m from the robot's centre: 0.03 m from its body, inside the 0.05 m margin
        ActorSpec person = new ActorSpec("p", ActorSpec.Kind.BODY, new ActorShape.Circle(0.25),
                List.of(new Point2d(0.48, -2), new Point2d(0.48, 2)), 0.5, ActorSpec.Repeat.ONCE, 0, 0, 0, 0);
        World w = new World(empty(), new Pose2d(0, 0, Math.PI / 2), RobotModel.ideal(0.1), LaserConfig.URG_04LX, 1L, 1L,
                List.of(person));
        for (int i = 0; i < 900; i++) {
            w.step(10 * MS);
        }
        assertEquals(0, w.contactCount());
        assertEquals(1, w.nearMisses(), "one approach within " + World.NEAR_MISS_MARGIN_M + " m");
        assertEquals(0.03, w.minClearanceM(), 1e-9);
    }
}
