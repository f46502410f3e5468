package io.rtaware.app.world;

import static org.junit.jupiter.api.Assertions.assertEquals;

import io.rtaware.core.data.Input;
import io.rtaware.core.data.Output;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.monitor.StepExecutor;
import io.rtaware.core.task.ErrorPolicy;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.ManualClock;
import io.rtaware.nav.NavConfig;
import io.rtaware.nav.NavController;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.robot.msg.RobotKeys;
import io.rtaware.robot.msg.VelocityCommand;
import io.rtaware.sim.map.OccupancyMap;
import io.rtaware.sim.scenario.Scenario;
import io.rtaware.sim.scenario.ScenarioLoader;
import io.rtaware.sim.world.LaserConfig;
import io.rtaware.sim.world.RobotModel;
import io.rtaware.sim.world.World;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/**
 * The ideal robot reproduces, bit for bit, the trajectory the code before the Koala model
 * (issue 17) drove: the paper's course with the default controller on the step executor
 * (no threads, manual clock), the world stepped every 10 ms, ground truth sampled every
 * 100 ms for the first 60 s. The expected CSV was recorded from that code (the world's
 * {@code RobotConfig.KOALA} constructor, before robot models existed).
 */
class IdealTrajectoryTest {

    private static final long MS = 1_000_000L;
    static final String RESOURCE = "/trajectories/paper-room-ideal-60s.csv";

    /**
     * The laser of the code the trajectory was recorded from: today's URG-04LX but with the 4 m
     * range it had before the SCIP 2.0 {@code DMAX:5600} was adopted (issue 35).
     */
    static final LaserConfig EARLIER_LASER = new LaserConfig(LaserConfig.URG_04LX.beams(),
            LaserConfig.URG_04LX.angleIncrementRad(), LaserConfig.URG_04LX.minRangeM(), 4.0,
            LaserConfig.URG_04LX.rateHz(), LaserConfig.URG_04LX.noiseSigmaM());

    /** The simulator as a task: steps the world, publishes what it produced, applies the motor command. */
    static final class WorldTask implements Task {
        private final World world;
        private Input<VelocityCommand> motor;
        private Output<LaserScan> laser;
        private Output<Odometry> odometry;
        private long lastNs = -1;

        WorldTask(World world) {
            this.world = world;
        }

        @Override
        public void initialize(TaskSetup setup) {
            motor = setup.consume(RobotKeys.MOTOR);
            laser = setup.produce(RobotKeys.LASER);
            odometry = setup.produce(RobotKeys.ODOMETRY);
        }

        @Override
        public void execute(long nowNs) {
            if (lastNs >= 0) {
                VelocityCommand cmd = motor.value();
                world.command(cmd.vxMps, cmd.omegaRadPerSec);
                world.step(nowNs - lastNs);
            }
            boolean first = lastNs < 0;
            lastNs = nowNs;
            if (first || world.odometryFresh()) {
                odometry.value().copyFrom(world.odometry());
                odometry.publish();
            }
            if (first || world.scanFresh()) {
                laser.value().copyFrom(world.scan());
                laser.publish();
            }
        }
    }

    static String trajectoryCsv(World world, Scenario scenario) {
        NavController nav = new NavController(NavConfig.builder()
                .goalToleranceM(scenario.goalToleranceM())
                .waypoints(scenario.waypoints())
                .grid(0.05, -1, -1, 11.6, 8.2)
                .build());
        Monitor.Builder builder = Monitor.builder(new ManualClock());
        builder.task(new TaskSpec("sim", Schedule.periodic(10 * MS), ErrorPolicy.STOP_ALL, new WorldTask(world)));
        nav.taskSpecs().forEach(builder::task);
        Monitor monitor = builder.build();
        StepExecutor step = monitor.startStepped();
        StringBuilder csv = new StringBuilder("t_s,x_m,y_m,yaw_rad\n");
        for (int i = 0; i <= 600; i++) {
            csv.append(i / 10.0).append(',').append(world.xM()).append(',').append(world.yM()).append(',')
                    .append(world.yawRad()).append('\n');
            step.runFor(100 * MS);
        }
        monitor.stop();
        return csv.toString();
    }

    static World idealWorld(Scenario scenario) {
        OccupancyMap map = scenario.map().orElseThrow();
        return new World(map, scenario.start(), RobotModel.named(RobotModel.IDEAL_NAME, 0.1), EARLIER_LASER, 1L);
    }

    @Test
    void idealRobotDrivesTheRecordedTrajectory() throws IOException {
        Scenario scenario = ScenarioLoader.load(ScenarioLoader.PAPER_ROOM);
        String expected;
        try (InputStream in = IdealTrajectoryTest.class.getResourceAsStream(RESOURCE)) {
            expected = new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
        assertEquals(expected, trajectoryCsv(idealWorld(scenario), scenario));
    }
}
