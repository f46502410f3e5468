package io.rtaware.app.ros2;

import io.rtaware.core.report.Rounding;
import io.rtaware.core.task.ErrorPolicy;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.ros2.graph.Ros2Context;
import io.rtaware.ros2.graph.Ros2Transport;
import io.rtaware.ros2.task.Ros2DataTask;
import io.rtaware.ros2.task.Ros2Stats;
import io.rtaware.sim.ros2.Ros2SimRobot;
import io.rtaware.sim.server.PlayerSimServer;
import io.rtaware.zenoh.ZenohException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.HdrHistogram.Histogram;

/**
 * The ROS 2 side of one {@code run --ros2}: the controller's Zenoh context and data task and,
 * without {@code --zenoh}, the built-in simulator served as a ROS 2 robot in the same process
 * (its own session listening on a free loopback port, the controller's session connecting to
 * it). Not thread-safe: built and closed by the command's thread.
 */
public final class Ros2Link implements AutoCloseable {

    /** Task name of the ROS 2 data task in reports. */
    public static final String TASK = "ros2";

    private final Ros2Options options;
    private final Ros2SimRobot simRobot;
    private final Ros2DataTask task;

    private Ros2Link(Ros2Options options, Ros2SimRobot simRobot, Ros2DataTask task) {
        this.options = options;
        this.simRobot = simRobot;
        this.task = task;
    }

    /**
     * Opens the sessions (and starts the simulator's ROS 2 side when there is no router).
     *
     * @param options what {@code --ros2} asked for
     * @param server the built-in simulator, or null when {@code --zenoh} names the robot's router
     * @return the link
     * @throws io.rtaware.app.UserError if a router cannot be reached
     */
    public static Ros2Link open(Ros2Options options, PlayerSimServer server) {
        if (options.dds() != null) {
            Ros2Context context = Ros2Wiring.openDds(options.dds());
            return new Ros2Link(options, null, Ros2DataTask.withDefaults(context, options.topics()));
        }
        Ros2SimRobot robot = null;
        List<String> connect;
        if (options.router() == null) {
            String endpoint = Ros2Wiring.freeLoopbackEndpoint();
            Ros2Context simContext = Ros2Wiring.open(List.of(), List.of(endpoint), options.topics().domain(),
                    options.distro());
            try {
                // its notices reach the run's summary and report through notices()
                robot = Ros2SimRobot.start(server, simContext, options.topics().namespace(), line -> { });
            } catch (ZenohException e) {
                throw new IllegalStateException("the simulator's ROS 2 side did not start: " + e.getMessage(), e);
            }
            connect = List.of(endpoint);
        } else {
            connect = List.of(options.router());
        }
        try {
            Ros2Context context = Ros2Wiring.open(connect, List.of(io.rtaware.zenoh.ZenohConfig.LOOPBACK_ANY_PORT),
                    options.topics().domain(), options.distro());
            return new Ros2Link(options, robot, Ros2DataTask.withDefaults(context, options.topics()));
        } catch (RuntimeException e) {
            closeQuietly(robot);
            throw e;
        }
    }

    /** @return the data task as the monitor runs it */
    public TaskSpec taskSpec() {
        return new TaskSpec(TASK, Schedule.continuous(), ErrorPolicy.CONTINUE, task);
    }

    /** @return where the robot is, for the start line */
    public String describe() {
        if (options.dds() != null) {
            return "ROS 2 robot over " + options.dds().describe();
        }
        return options.router() == null ? "built-in simulator as a ROS 2 robot over Zenoh on loopback"
                : "ROS 2 robot through Zenoh at " + options.router();
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
        return new Ros2Section(describe(), transport(), options.distro().cliName(), s.scans(), s.odometry(), s.commands(),
                rejected, s.malformed(), s.oversized(), s.overflowed(), s.otherPublishers(), s.clockEpochs(), notices(),
                s.lastProblem(), task.fault(), latencyMs, task.latencySource(),
                Rounding.toDecimals(cpuUsPerSample(s), 2), s.droppedBeams());
    }

    /** @return {@code rmw_zenoh} or {@code dds} */
    private String transport() {
        return (options.dds() != null ? Ros2Transport.DDS : Ros2Transport.RMW_ZENOH).reportName();
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
