package io.rtaware.bench;

import io.rtaware.sim.scenario.Scenario;
import io.rtaware.sim.scenario.ScenarioLoader;
import io.rtaware.sim.world.LaserConfig;
import io.rtaware.sim.world.RobotConfig;
import io.rtaware.sim.world.World;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;

/**
 * Cost of one 10 ms world step in {@code paper-room} with no controller attached: kinematics,
 * collision checks, 16 Hz odometry and the 10 Hz 683-beam laser amortised over the steps. The
 * fastest real-time factor of the simulator is {@code 10 ms / score}. The robot drives a slow
 * circle so it keeps moving without hitting anything. Run:
 * {@code java -jar rtaware-bench/target/benchmarks.jar WorldStep -f 1 -wi 2 -i 3}.
 * JMH state; one instance per benchmark thread.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
public class WorldStepBench {

    private World world;

    /** Builds the world and starts the robot on a circle. */
    @Setup
    public void setup() {
        Scenario s = ScenarioLoader.load(ScenarioLoader.PAPER_ROOM);
        world = new World(s.map().orElseThrow(), new io.rtaware.robot.geometry.Pose2d(2.0, 1.5, 0.0),
                RobotConfig.KOALA, LaserConfig.URG_04LX, 1L);
        world.command(0.1, 0.2);
    }

    /**
     * One 10 ms world step.
     *
     * @return the world time (consumed by JMH)
     */
    @Benchmark
    public long step10ms() {
        world.step(10_000_000L);
        return world.timeNs();
    }
}
