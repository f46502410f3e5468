package io.rtaware.ros2msg;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import io.rtaware.core.monitor.CycleOutcome;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.OccupancyGrid;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.robot.msg.PlannedPath;
import io.rtaware.robot.msg.VelocityCommand;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.cdr.CdrWriter;
import io.rtaware.ros2msg.statistics.TimingStatistics;
import io.rtaware.ros2msg.value.DiagnosticArray;
import io.rtaware.ros2msg.value.DiagnosticStatus;
import io.rtaware.ros2msg.value.MetricsMessage;
import io.rtaware.ros2msg.value.PlanarPose;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.lang.management.ManagementFactory;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Encoding and decoding every type, and the statistics of a run, once warmed up, allocate nothing. */
class SteadyStateAllocationTest {

    private final CdrWriter writer = new CdrWriter(1 << 20);
    private final CdrReader reader = new CdrReader();
    private final Ros2Header header = new Ros2Header().set(1_000, "map");
    private final LaserScanCodec laserCodec = new LaserScanCodec();
    private final OdometryCodec odometryCodec = new OdometryCodec("base_link");
    private final TwistCodec twistCodec = new TwistCodec();
    private final PathCodec pathCodec = new PathCodec();
    private final OccupancyGridCodec gridCodec = new OccupancyGridCodec();
    private final PoseStampedCodec poseCodec = new PoseStampedCodec();
    private final DiagnosticArrayCodec diagnosticsCodec = new DiagnosticArrayCodec();
    private final LaserScan scan = new LaserScan(361);
    private final Odometry odometry = new Odometry();
    private final VelocityCommand command = new VelocityCommand();
    private final PlannedPath path = new PlannedPath(100);
    private final OccupancyGrid grid = new OccupancyGrid(100 * 100);
    private final PlanarPose pose = new PlanarPose();
    private final DiagnosticArray diagnostics = new DiagnosticArray(4, 4);
    private final MetricsMessageCodec metricsCodec = new MetricsMessageCodec();
    private final MetricsMessage metrics = new MetricsMessage(5);
    private long checksum;

    private <T> void roundTrip(Ros2Codec<T> codec, T value) {
        codec.encode(header, value, writer);
        codec.decode(reader.wrap(writer.buffer(), 0, writer.size()), header, value);
        checksum += writer.size();
    }

    private void allTypes() {
        roundTrip(laserCodec, scan);
        roundTrip(odometryCodec, odometry);
        roundTrip(twistCodec, command);
        roundTrip(pathCodec, path);
        roundTrip(gridCodec, grid);
        roundTrip(poseCodec, pose);
        roundTrip(diagnosticsCodec, diagnostics);
        roundTrip(metricsCodec, metrics);
    }

    @Test
    void roundTripsAllocateNothing() {
        scan.setCount(361);
        path.setCount(100);
        grid.setGeometry(100, 100, 0.05, -2.5, -2.5);
        DiagnosticStatus status = diagnostics.add();
        status.name.append("planner");
        status.message.append("ok");
        status.key(status.addValue()).append("misses");
        metrics.measurementSourceName.append("planner");
        metrics.metricsSource.append("execution_time");
        metrics.unit.append("ms");
        metrics.add(MetricsMessage.AVERAGE, 2.5);
        metrics.add(MetricsMessage.SAMPLE_COUNT, 10);
        assertEquals(0, leastAllocated(this::allTypes, 20_000, 5_000),
                "bytes allocated by 40 000 encodes and decodes (checksum " + checksum + ")");
    }

    private long world;
    private long generation;
    private final long[] inputs = new long[1];

    /** A second of world time of two tasks, one producing a key at 100 Hz, one reading it at 10 Hz. */
    private void aSecond(TimingStatistics statistics) {
        try {
            for (int i = 0; i < 100; i++) {
                world += 10_000_000L;
                statistics.commit(0, ++generation, world);
                statistics.cycle(0, CycleOutcome.OK, world - 2_000_000L, world - 1_000_000L, world, null);
                if (i % 10 == 9) {
                    inputs[0] = generation - 1;
                    statistics.cycle(1, CycleOutcome.MISS, world - 1_000_000L, world, world + 500_000L, inputs);
                }
                statistics.drained(Long.MIN_VALUE);
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @Test
    void statisticsOfARunAllocateNothing() {
        TimingStatistics statistics = new TimingStatistics(List.of("sensor", "planner"),
                List.of(List.of(), List.of("scan")), List.of("scan"), 0, 0, 1_000_000_000L, (m, stopNs) -> {
                    metricsCodec.encode(header, m, writer);
                    checksum += writer.size();
                });
        assertEquals(0, leastAllocated(() -> aSecond(statistics), 200, 50), "bytes allocated by 50 s of statistics");
        assertEquals(0, statistics.lateRecords() + statistics.unmatchedAges());
        assertEquals(statistics.windowsPublished() * 10, statistics.messagesPublished());
    }

    /**
     * Runs {@code work} {@code warmUp} times, then in rounds of {@code perRound} until a round
     * allocates nothing, at most 20 rounds: a round can catch a one-off allocation of the runtime,
     * and on a busy machine the JIT may not yet have compiled (and so scalar-replaced) every path
     * after the warm-up (seen once: 80 B in each of three rounds). A real allocation per call
     * shows in every round.
     *
     * @return the bytes the least allocating round allocated
     */
    private static long leastAllocated(Runnable work, int warmUp, int perRound) {
        com.sun.management.ThreadMXBean threads =
                (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        assumeTrue(threads.isThreadAllocatedMemorySupported(), "thread allocation counting unsupported");
        for (int i = 0; i < warmUp; i++) {
            work.run();
        }
        long id = Thread.currentThread().getId();
        long allocated = Long.MAX_VALUE;
        for (int round = 0; round < 20 && allocated != 0; round++) {
            long before = threads.getThreadAllocatedBytes(id);
            for (int i = 0; i < perRound; i++) {
                work.run();
            }
            allocated = Math.min(allocated, threads.getThreadAllocatedBytes(id) - before);
        }
        return allocated;
    }
}
