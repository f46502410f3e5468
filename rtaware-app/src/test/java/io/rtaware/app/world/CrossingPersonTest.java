package io.rtaware.app.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.monitor.StepExecutor;
import io.rtaware.core.task.ErrorPolicy;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.ManualClock;
import io.rtaware.nav.NavConfig;
import io.rtaware.nav.NavController;
import io.rtaware.robot.geometry.Point2d;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.sim.actor.ActorShape;
import io.rtaware.sim.actor.ActorSpec;
import io.rtaware.sim.map.OccupancyMap;
import io.rtaware.sim.world.LaserConfig;
import io.rtaware.sim.world.RobotModel;
import io.rtaware.sim.world.World;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/**
 * The paper's claim where it can bite: a person crosses in front of the Koala; with the obstacle
 * avoider at 800 ms the robot walks into them, at 50 ms it does not. The controller and the world
 * run on the step executor (no threads, manual clock, the world stepped every 10 ms), one fixed
 * seed, so the outcome is exact and repeatable.
 */
class CrossingPersonTest {

    static final long MS = 1_000_000L;
    static final double SPEED_MPS = 0.4;

    /** A 12 x 4 m hall with 0.2 m walls, the robot's lane along y = 2. */
    static OccupancyMap hall() {
        int w = 124;
        int h = 44;
        OccupancyMap.CellState[] cells = new OccupancyMap.CellState[w * h];
        for (int row = 0; row < h; row++) {
            for (int col = 0; col < w; col++) {
                boolean wall = row < 2 || row >= h - 2 || col < 2 || col >= w - 2;
                cells[row * w + col] = wall ? OccupancyMap.CellState.OCCUPIED : OccupancyMap.CellState.FREE;
            }
        }
        return new OccupancyMap("hall", w, h, 0.1, -0.2, -0.2, cells);
    }

    /** A person who starts walking across the lane when the robot comes within 2.5 m, at 0.5 m/s. */
    static ActorSpec person() {
        return new ActorSpec("person", ActorSpec.Kind.BODY, new ActorShape.Circle(0.25),
                List.of(new Point2d(4.0, 0.3), new Point2d(4.0, 3.7)), 0.5, ActorSpec.Repeat.ONCE, 0, 2.5, 0, 0);
    }

    /**
     * The laser this crossing was laid out and measured with (docs/moving-world.md): the URG-04LX at
     * the 4 m range the model had before it took SCIP 2.0's {@code DMAX:5600} (issue 35). At 5.6 m
     * this one crossing (trigger 2.5 m, seed 7) is not hit at any avoider period: the robot passes
     * 0.405 m from the person at 50, 200, 400 and 800 ms alike (stepped, 2026-11-28). Kept at 4 m
     * so the test still shows what the avoider's period does when the person is hit; the dependence
     * on the range is stated in docs/moving-world.md.
     */
    static final LaserConfig HALL_LASER = IdealTrajectoryTest.EARLIER_LASER;

    /** @return the world after the robot drove the hall with the avoider at {@code obstacleMs} */
    static World drive(long obstacleMs, long seconds) {
        RobotModel koala = RobotModel.koala(SPEED_MPS);
        World world = new World(hall(), new Pose2d(1.0, 2.0, 0), koala, HALL_LASER, 7L, 1L, List.of(person()));
        NavController nav = new NavController(NavConfig.builder()
                .topSpeedMps(SPEED_MPS)
                .inflationMarginM(0)
                .reactionLimits(koala.stoppingDistanceM(SPEED_MPS), koala.laserDelayNs(HALL_LASER))
                .obstacleSpeedMps(0.5)
                .periodsNs(Map.of("obstacle", obstacleMs * MS))
                .goalToleranceM(0.3)
                .waypoints(List.of(new Point2d(10.0, 2.0)))
                .grid(0.05, -1, -1, 14, 6)
                .build());
        Monitor.Builder builder = Monitor.builder(new ManualClock());
        builder.task(new TaskSpec("sim", Schedule.periodic(10 * MS), ErrorPolicy.STOP_ALL,
                new IdealTrajectoryTest.WorldTask(world)));
        nav.taskSpecs().forEach(builder::task);
        Monitor monitor = builder.build();
        StepExecutor step = monitor.startStepped();
        step.runFor(seconds * 1000 * MS);
        monitor.stop();
        return world;
    }

    @Test
    void aPersonCrossingInFrontOfARobotWhoseAvoiderRunsAt800MsIsHitAndAt50MsIsNot() {
        World slow = drive(800, 30);
        World fast = drive(50, 30);
        assertTrue(slow.contactCount() >= 1, "the avoider at 800 ms: the robot hits the person ("
                + slow.contactCount() + " contacts, nearest " + slow.minClearanceM() + " m)");
        assertEquals(0, fast.contactCount(), "the avoider at 50 ms: no contact (nearest " + fast.minClearanceM() + " m)");
        assertTrue(fast.xM() > 5.0, "and the robot went on past the crossing: x = " + fast.xM());
    }
}
