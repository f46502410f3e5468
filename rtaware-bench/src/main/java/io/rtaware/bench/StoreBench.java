package io.rtaware.bench;

import io.rtaware.core.data.Key;
import io.rtaware.core.data.StateVariable;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.Odometry;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Group;
import org.openjdk.jmh.annotations.GroupThreads;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

/**
 * The data store's cost per cycle: a producer's commit and a consumer's copy-in of a 683-beam
 * scan (the Hokuyo URG-04LX) and of a pose. The copy-in benchmarks force a real copy each time
 * (the consumer's held generation is always behind), which is the worst case: an unchanged key
 * costs one volatile read.
 *
 * <p>Run: {@code java -jar rtaware-bench/target/benchmarks.jar StoreBench}
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class StoreBench {

    /** One scan variable and one pose variable, filled once. */
    @State(Scope.Group)
    public static class Store {
        final StateVariable<LaserScan> scan =
                new StateVariable<>(Key.of("laser", LaserScan.class, LaserScan::new));
        final StateVariable<Odometry> pose =
                new StateVariable<>(Key.of("odometry", Odometry.class, Odometry::new));
        final LaserScan producedScan = new LaserScan();
        final Odometry producedPose = new Odometry();
        long nowNs;

        /** Fills the producer buffers and commits once. */
        @Setup(Level.Trial)
        public void fill() {
            producedScan.setCount(683);
            for (int i = 0; i < 683; i++) {
                producedScan.rangesM[i] = 0.5f + i * 0.001f;
            }
            producedScan.minAngleRad = -2.094;
            producedScan.maxAngleRad = 2.094;
            producedPose.xM = 1;
            scan.commit(producedScan, 1);
            pose.commit(producedPose, 1);
        }
    }

    /** A consumer's own buffers and cursors. */
    @State(Scope.Thread)
    public static class Consumer {
        final LaserScan scan = new LaserScan();
        final Odometry pose = new Odometry();
        final StateVariable.ReadCursor cursor = new StateVariable.ReadCursor();
    }

    /**
     * @param s the store
     * @return the scan variable's generation
     */
    @Benchmark
    @Group("scanCommit")
    public long scanCommit(Store s) {
        s.scan.commit(s.producedScan, ++s.nowNs);
        return s.scan.generation();
    }

    /**
     * @param s the store
     * @param c the consumer
     * @return a value from the copy
     */
    @Benchmark
    @Group("scanCopyIn")
    public float scanCopyIn(Store s, Consumer c) {
        s.scan.copyTo(c.scan, -1, c.cursor);
        return c.scan.rangesM[682];
    }

    /**
     * Copy-in plus commit: one full cycle of a task that reads a scan and republishes it.
     *
     * @param s the store
     * @param c the consumer
     * @return a value from the copy
     */
    @Benchmark
    @Group("scanCopyInPlusCommit")
    public float scanCopyInPlusCommit(Store s, Consumer c) {
        s.scan.copyTo(c.scan, -1, c.cursor);
        s.scan.commit(s.producedScan, ++s.nowNs);
        return c.scan.rangesM[0];
    }

    /**
     * @param s the store
     * @param c the consumer
     * @return a value from the copy
     */
    @Benchmark
    @Group("poseCopyInPlusCommit")
    public double poseCopyInPlusCommit(Store s, Consumer c) {
        s.pose.copyTo(c.pose, -1, c.cursor);
        s.pose.commit(s.producedPose, ++s.nowNs);
        return c.pose.xM;
    }

    /**
     * Readers copying the scan while a writer commits flat out: the contended case.
     *
     * @param s the store
     * @param c the consumer
     * @return a value from the copy
     */
    @Benchmark
    @Group("scanContended")
    @GroupThreads(2)
    public float scanContendedReaders(Store s, Consumer c) {
        s.scan.copyTo(c.scan, -1, c.cursor);
        return c.scan.rangesM[682];
    }

    /**
     * The writer of the contended case.
     *
     * @param s the store
     * @return the generation
     */
    @Benchmark
    @Group("scanContended")
    @GroupThreads(1)
    public long scanContendedWriter(Store s) {
        s.scan.commit(s.producedScan, ++s.nowNs);
        return s.scan.generation();
    }
}
