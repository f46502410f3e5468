package io.rtaware.bench;

import io.rtaware.robot.msg.LaserScan;
import io.rtaware.sim.map.OccupancyMap;
import io.rtaware.sim.map.RayCaster;
import io.rtaware.sim.scenario.ScenarioLoader;
import io.rtaware.sim.world.Laser;
import io.rtaware.sim.world.LaserConfig;
import java.util.SplittableRandom;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;

/**
 * Cost of one simulated Hokuyo URG-04LX scan (683 beams, 4 m, 1 cm noise) in the built-in
 * {@code paper-room}, from a rotating set of free poses. Run:
 * {@code java -jar rtaware-bench/target/benchmarks.jar RayCast -f 1 -wi 2 -i 3}.
 * JMH state; one instance per benchmark thread.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
public class RayCastBench {

    private static final int POSES = 64;

    private Laser laser;
    private LaserScan scan;
    private SplittableRandom noise;
    private double[] xs;
    private double[] ys;
    private double[] yaws;
    private int next;

    /** Loads the map and picks the poses. */
    @Setup
    public void setup() {
        OccupancyMap map = ScenarioLoader.load(ScenarioLoader.PAPER_ROOM).map().orElseThrow();
        laser = new Laser(LaserConfig.URG_04LX, new RayCaster(map));
        scan = new LaserScan(LaserConfig.URG_04LX.beams());
        noise = new SplittableRandom(1);
        SplittableRandom r = new SplittableRandom(2);
        xs = new double[POSES];
        ys = new double[POSES];
        yaws = new double[POSES];
        for (int i = 0; i < POSES; i++) {
            do {
                xs[i] = 0.2 + r.nextDouble() * 9.2;
                ys[i] = 0.2 + r.nextDouble() * 5.8;
            } while (map.clearanceM(xs[i], ys[i], 0.2) < 0.2);
            yaws[i] = r.nextDouble() * 2 * Math.PI;
        }
    }

    /**
     * One full scan.
     *
     * @return the scan (consumed by JMH)
     */
    @Benchmark
    public LaserScan scan683() {
        int i = next;
        next = (i + 1) & (POSES - 1);
        laser.scan(xs[i], ys[i], yaws[i], 0.0, noise, scan);
        return scan;
    }
}
