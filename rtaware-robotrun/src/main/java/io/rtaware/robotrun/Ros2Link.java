package io.rtaware.robotrun;

import io.rtaware.core.report.Rounding;
import io.rtaware.core.task.ErrorPolicy;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.ros2.graph.Ros2Distro;
import io.rtaware.ros2.graph.Ros2Transport;
import io.rtaware.ros2.task.Ros2DataTask;
import io.rtaware.ros2.task.Ros2Stats;
import io.rtaware.sim.ros2.Ros2SimRobot;
import io.rtaware.zenoh.ZenohException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.TimeUnit;
import org.HdrHistogram.Histogram;

/**
 * The ROS 2 side of a run whose robot is a ROS 2 robot: the controller's ROS 2 data task (on a
 * Zenoh context of its own) and, when the built-in simulator serves as the robot in the same
 * process, the simulator's ROS 2 robot; the data task's counters as one summary line and as the
 * report's {@code ros2} section. The caller opens the contexts (a peer session on loopback, a
 * router's endpoint, or the DDS bridge) and the simulator's robot; the link owns both from then
 * on. Not thread-safe: built and closed by the run's thread.
 */
public final class Ros2Link implements AutoCloseable {

    /** Task name of the ROS 2 data task in reports. */
    public static final String TASK = "ros2";

    private final Ros2DataTask task;
    private final Ros2SimRobot simRobot;
    private final String describe;
    private final Ros2Transport transport;
    private final Ros2Distro distro;

    /**
     * @param task the controller's data task (it closes its own context when the monitor stops)
     * @param simRobot the built-in simulator's ROS 2 robot, or null for another robot; closed with the link
     * @param describe where the robot is, in words (the start line, the report's {@code robot})
     * @param transport how the robot is reached
     * @param distro the ROS 2 distribution whose conventions are followed
     */
    public Ros2Link(Ros2DataTask task, Ros2SimRobot simRobot, String describe, Ros2Transport transport,
                    Ros2Distro distro) {
        this.task = Objects.requireNonNull(task, "task");
        this.simRobot = simRobot;
        this.describe = Objects.requireNonNull(describe, "describe");
        this.transport = Objects.requireNonNull(transport, "transport");
        this.distro = Objects.requireNonNull(distro, "distro");
    }

    /** @return the data task as the monitor runs it */
    public TaskSpec taskSpec() {
        return new TaskSpec(TASK, Schedule.continuous(), ErrorPolicy.CONTINUE, task);
    }

    /** @return where the robot is, for the start line */
    public String describe() {
        return describe;
    }

    /**
     * @return one line with the data task's counters, scan latency and CPU cost per sample, then
     *     one line ({@code ros2: notice: ...}) per event reported once ({@link #notices()})
     */
    public String summary() {
        Ros2Stats s = task.stats();
        Histogram latency = task.latencySnapshot();
        String latencyText = task.latencySource() == null
                ? "scan latency unknown (no source timestamps: the robot's stamps are not wall-clock times)"
                : String.format(Locale.ROOT, "scan source-to-commit latency p50 %.2f ms p99 %.2f ms (from the %s)",
                        latencyMs(latency, 50), latencyMs(latency, 99), task.latencySource());
        StringBuilder text = new StringBuilder(String.format(Locale.ROOT,
                "ros2 (%s): %d scans, %d odometry, %d commands; dropped %d (malformed %d, oversized %d, implausible %d, "
                        + "behind %d, other publishers %d); clock epochs %d; %s; data task CPU %.1f us/sample",
                transport(), s.scans(), s.odometry(), s.commands(), s.dropped(), s.malformed(), s.oversized(), s.rejected(),
                s.overflowed(), s.otherPublishers(), s.clockEpochs(), latencyText, cpuUsPerSample(s)));
        for (String notice : notices()) {
            text.append(System.lineSeparator()).append("ros2: notice: ").append(notice);
        }
        return text.toString();
    }

    /**
     * @return the events reported once: the data task's (other publishers on its input topics,
     *     clock epochs), then the built-in simulator's (other publishers on its {@code cmd_vel})
     */
    public List<String> notices() {
        List<String> all = new ArrayList<>(task.notices());
        if (simRobot != null) {
            simRobot.notices().forEach(n -> all.add("simulator: " + n));
        }
        return all;
    }

    /** @return the {@code ros2} section of the run's report */
    public Ros2Section section() {
        Ros2Stats s = task.stats();
        Histogram latency = task.latencySnapshot();
        Map<String, Long> rejected = new LinkedHashMap<>();
        rejected.put(task.topics().qualifiedScan(), s.scanRejected());
        rejected.put(task.topics().qualifiedOdom(), s.odomRejected());
        Map<String, Double> latencyMs = null;
        if (task.latencySource() != null) {
            latencyMs = new LinkedHashMap<>();
            latencyMs.put("p50", Rounding.toDecimals(latencyMs(latency, 50), 3));
            latencyMs.put("p99", Rounding.toDecimals(latencyMs(latency, 99), 3));
        }
        return new Ros2Section(describe(), transport(), distro.cliName(), s.scans(), s.odometry(), s.commands(),
                rejected, s.malformed(), s.oversized(), s.overflowed(), s.otherPublishers(), s.clockEpochs(), notices(),
                s.lastProblem(), task.fault(), latencyMs, task.latencySource(),
                Rounding.toDecimals(cpuUsPerSample(s), 2), s.droppedBeams());
    }

    /** @return {@code rmw_zenoh} or {@code dds} */
    private String transport() {
        return transport.reportName();
    }

    /** @return a percentile of the scan source-to-commit latency, milliseconds */
    private static double latencyMs(Histogram latencyNs, double percentile) {
        return latencyNs.getValueAtPercentile(percentile) / 1e6;
    }

    /** @return the data task's thread CPU time per scan or odometry sample received, microseconds */
    private double cpuUsPerSample(Ros2Stats s) {
        long samples = s.scans() + s.odometry();
        return samples == 0 ? 0.0 : task.cpuNs() / (double) samples / TimeUnit.MICROSECONDS.toNanos(1);
    }

    /** @return the data task */
    public Ros2DataTask task() {
        return task;
    }

    /** Stops the simulator's ROS 2 side, if any (the data task closes its own session). */
    @Override
    public void close() {
        closeQuietly(simRobot);
    }

    private static void closeQuietly(Ros2SimRobot robot) {
        if (robot != null) {
            try {
                robot.close();
            } catch (ZenohException e) {
                // the process is leaving this robot; nothing else holds its session
            }
        }
    }
}
