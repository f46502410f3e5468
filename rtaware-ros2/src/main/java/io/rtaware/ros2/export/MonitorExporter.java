package io.rtaware.ros2.export;

import io.rtaware.core.agent.AgentThread;
import io.rtaware.core.data.FeedStats;
import io.rtaware.core.data.StateValue;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.monitor.TaskInfo;
import io.rtaware.core.time.EpochClock;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.ros2.graph.QosProfile;
import io.rtaware.ros2.graph.Ros2Context;
import io.rtaware.ros2.graph.Ros2Node;
import io.rtaware.ros2.graph.Ros2Publisher;
import io.rtaware.ros2msg.DiagnosticArrayCodec;
import io.rtaware.ros2msg.MetricsMessageCodec;
import io.rtaware.ros2msg.RobotTopics;
import io.rtaware.ros2msg.Ros2Header;
import io.rtaware.ros2msg.Ros2Types;
import io.rtaware.ros2msg.TaskDiagnostics;
import io.rtaware.ros2msg.TransformMessages;
import io.rtaware.ros2msg.cdr.CdrWriter;
import io.rtaware.ros2msg.statistics.TimingStatistics;
import io.rtaware.ros2msg.value.DiagnosticArray;
import io.rtaware.ros2msg.value.DiagnosticStatus;
import io.rtaware.ros2msg.value.MetricsMessage;
import io.rtaware.ros2msg.value.PlanarTransform;
import io.rtaware.zenoh.ZenohException;
import java.io.IOException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.TimeUnit;
import org.agrona.concurrent.Agent;
import org.agrona.concurrent.AgentTerminationException;
import org.agrona.concurrent.SleepingIdleStrategy;

/**
 * Publishes a monitor's keys and health over ROS 2 from a thread of its own (never a task's):
 * every {@code keyPeriodMs} of wall time each {@link ExportedKey} whose generation changed is
 * read from the store (a copy, under the key's read lock, like any observer) and published as
 * its ROS 2 type on {@link ExportedKey#topic()}; once a second a
 * {@code diagnostic_msgs/msg/DiagnosticArray} on {@code /diagnostics} carries one status per task
 * (period, releases, misses, miss %, stale runs, errors, execution-time p99 of the latest cycles
 * against the period; WARN when misses grew since the last array, ERROR when errors did) and
 * one per key (commits, rate, producer, and the topic it is published on or that it has no
 * ROS 2 type). Frames as REP 105 names them: each value of an odometry key that names a
 * {@link ExportedKey#transformChild()} is also published on {@code /tf} as the transform from
 * its frame to that child, stamped as its message; the static transforms given are published
 * on {@code /tf_static} (offered transient local, as tf2's static broadcaster offers them, and,
 * since this Zenoh layer keeps no history for late subscribers, again with every health
 * array). On {@value #STATISTICS}, ROS 2's topic statistics of every task and key
 * ({@code statistics_msgs/msg/MetricsMessage}, {@link TimingStatistics}): a listener copies every
 * commit and cycle record into a ring on the thread that reports it ({@code TimingFeed}), and the
 * exporter's thread turns them into one message per metric, task and key for every second of
 * world time (the monitor's clock, the first window starting when the exporter starts), stamped
 * in Unix-epoch time (the wall clock when the exporter started plus the world time since),
 * published as soon as each second is complete. Its thread, an {@link AgentThread}, is named
 * {@value #THREAD_NAME}, outside the {@code rtaware-*} threads whose allocation {@code bench}
 * measures; a failing publication ends it, and {@link #failure()} says why. Thread-safe:
 * {@link #close()} from any thread.
 */
public final class MonitorExporter implements AutoCloseable {

    /** Node name of the exporter in the ROS graph. */
    public static final String NODE_NAME = "rtaware_monitor";
    /** Topic of the health array. */
    public static final String DIAGNOSTICS = "/diagnostics";
    /** Topic of the topic statistics. */
    public static final String STATISTICS = "/statistics";
    /**
     * World time after a second's end after which its statistics are published even if a task has
     * not reported past it (one that has gone quiet): see {@link TimingStatistics}.
     */
    public static final long STATISTICS_GRACE_NS = TimeUnit.SECONDS.toNanos(1);
    /** The history depth tf2's broadcaster offers on {@code /tf}. */
    private static final int TF_DEPTH = 100;
    /** The name of the exporter's thread. */
    public static final String THREAD_NAME = "ros2-export";
    private static final long DIAGNOSTICS_PERIOD_NS = TimeUnit.SECONDS.toNanos(1);
    private static final int VALUES_PER_STATUS = TaskDiagnostics.VALUES;
    private static final int MAX_MESSAGE_BYTES = 1 << 20;

    private final Monitor monitor;
    private final Ros2Context context;
    private final long keyPeriodNs;
    private final List<Slot<?>> slots = new ArrayList<>();
    private final Map<String, String> topicByKey = new HashMap<>();
    private final Ros2Publisher diagnostics;
    /** {@code /tf}, or null when no key makes transforms. */
    private final Ros2Publisher tf;
    /** {@code /tf_static}, or null without static transforms. */
    private final Ros2Publisher tfStatic;
    private final List<PlanarTransform> staticTransforms;
    private final DiagnosticArrayCodec diagnosticCodec = new DiagnosticArrayCodec();
    private final Ros2Publisher statisticsPublisher;
    private final MetricsMessageCodec metricsCodec = new MetricsMessageCodec();
    private final TimingFeed feed;
    private final TimingStatistics statistics;
    private final DiagnosticArray array;
    private final CdrWriter writer = new CdrWriter(MAX_MESSAGE_BYTES);
    private final Ros2Header header = new Ros2Header();
    private final EpochClock epoch = new EpochClock();
    private final TaskDiagnostics taskDiagnostics;
    /** The publishing loop, started once the node and publishers are declared. */
    private volatile AgentThread loop;
    private volatile String failure;
    private volatile long arraysPublished;

    /** One exported key: its buffer, last generation seen and publisher. */
    private static final class Slot<T extends StateValue<T>> {
        final ExportedKey<T> exported;
        final T buffer;
        final Ros2Publisher publisher;
        long generation;

        Slot(ExportedKey<T> exported, Ros2Publisher publisher) {
            this.exported = exported;
            this.buffer = exported.key().newBuffer();
            this.publisher = publisher;
        }
    }

    private MonitorExporter(Monitor monitor, Ros2Context context, List<ExportedKey<?>> keys,
                            List<PlanarTransform> staticTransforms, long keyPeriodMs) throws ZenohException {
        this.monitor = monitor;
        this.context = context;
        this.keyPeriodNs = TimeUnit.MILLISECONDS.toNanos(keyPeriodMs);
        this.staticTransforms = List.copyOf(staticTransforms);
        Ros2Node node = context.createNode("/", NODE_NAME);
        boolean transforms = false;
        for (ExportedKey<?> k : keys) {
            if (monitor.hasKey(k.key().name())) {
                slots.add(slot(node, k));
                topicByKey.put(k.key().name(), k.topic());
                transforms |= k.transformChild() != null;
            }
        }
        tf = transforms ? node.createPublisher(RobotTopics.TF, Ros2Types.TF_MESSAGE, new QosProfile(true, false, TF_DEPTH),
                MAX_MESSAGE_BYTES) : null;
        tfStatic = this.staticTransforms.isEmpty() ? null
                : node.createPublisher(RobotTopics.TF_STATIC, Ros2Types.TF_MESSAGE, new QosProfile(true, true, 1), MAX_MESSAGE_BYTES);
        diagnostics = node.createPublisher(DIAGNOSTICS, diagnosticCodec.type(), QosProfile.defaults(), MAX_MESSAGE_BYTES);
        statisticsPublisher = node.createPublisher(STATISTICS, metricsCodec.type(), QosProfile.defaults(),
                MAX_MESSAGE_BYTES);
        List<TaskInfo> tasks = monitor.tasks();
        long worldNowNs = monitor.clock().nanos();
        statistics = new TimingStatistics(tasks.stream().map(TaskInfo::name).toList(),
                tasks.stream().map(TaskInfo::inputKeys).toList(), monitor.keyNames(), worldNowNs,
                epoch.epochNanos() - worldNowNs, STATISTICS_GRACE_NS, this::publishStatistics);
        feed = TimingFeed.of(tasks);
        monitor.addListener(feed);
        int statuses = monitor.tasks().size() + monitor.keyNames().size();
        array = new DiagnosticArray(statuses, VALUES_PER_STATUS);
        taskDiagnostics = TaskDiagnostics.of(monitor.tasks());
    }

    private static <T extends StateValue<T>> Slot<T> slot(Ros2Node node, ExportedKey<T> k) throws ZenohException {
        return new Slot<>(k, node.createPublisher(k.topic(), k.codec().type(), QosProfile.defaults(), MAX_MESSAGE_BYTES));
    }

    /**
     * Declares the node and publishers and starts the thread.
     *
     * @param monitor the monitor to export (built, not started: the exporter listens to its
     *     cycles and commits from the start)
     * @param context an open context, owned by the exporter from now on
     * @param keys the keys with a ROS 2 type (keys the monitor does not have are left out)
     * @param staticTransforms what {@code /tf_static} carries (none: no such topic)
     * @param keyPeriodMs how often the keys are looked at, in wall milliseconds
     * @return the running exporter
     * @throws ZenohException if a declaration fails (the context is closed then)
     * @throws IllegalStateException if the monitor has started (the context is closed then)
     */
    public static MonitorExporter start(Monitor monitor, Ros2Context context, List<ExportedKey<?>> keys,
                                        List<PlanarTransform> staticTransforms, long keyPeriodMs)
            throws ZenohException {
        Objects.requireNonNull(monitor, "monitor");
        if (keyPeriodMs <= 0) {
            throw new IllegalArgumentException("key period must be positive, got " + keyPeriodMs + " ms");
        }
        try {
            MonitorExporter e = new MonitorExporter(monitor, context, keys, staticTransforms, keyPeriodMs);
            e.loop = AgentThread.start(e.new Publishing(), new SleepingIdleStrategy(e.keyPeriodNs), e::stopped);
            return e;
        } catch (ZenohException | RuntimeException e) {
            context.close();
            throw e;
        }
    }

    /**
     * The exporter's loop: the statistics of what the monitor reported since the last turn, the
     * keys whose generation changed every key period, the health array once a second; a failing
     * publication ends it ({@link #stopped}).
     */
    private final class Publishing implements Agent {
        private long nextDiagnosticsNs;

        @Override
        public void onStart() {
            nextDiagnosticsNs = System.nanoTime();
        }

        @Override
        public int doWork() {
            try {
                feed.drainInto(statistics);
                statistics.drained(monitor.clock().nanos());
                for (Slot<?> s : slots) {
                    publishIfNew(s);
                }
                if (System.nanoTime() - nextDiagnosticsNs >= 0) {
                    publishStaticTransforms();
                    publishDiagnostics();
                    nextDiagnosticsNs += DIAGNOSTICS_PERIOD_NS;
                }
            } catch (IOException | RuntimeException e) {
                throw new AgentTerminationException(e);
            }
            return 0; // always idle a key period: the keys are looked at that often
        }

        @Override
        public String roleName() {
            return THREAD_NAME;
        }
    }

    /** The loop ended on a failure: kept for {@link #failure()}. */
    private void stopped(Throwable error) {
        Throwable cause = error instanceof AgentTerminationException && error.getCause() != null ? error.getCause() : error;
        failure = cause.getMessage() == null ? cause.toString() : cause.getMessage();
    }

    private <T extends StateValue<T>> void publishIfNew(Slot<T> s) throws ZenohException {
        long generation = monitor.read(s.exported.key(), s.buffer);
        if (generation == 0 || generation == s.generation) {
            return;
        }
        s.generation = generation;
        long nowNs = epoch.epochNanos();
        s.exported.codec().encode(header.set(nowNs, s.exported.frameId()), s.buffer, writer);
        s.publisher.publish(writer.buffer(), writer.size(), nowNs);
        if (s.exported.transformChild() != null && s.buffer instanceof Odometry odometry) {
            TransformMessages.begin(writer, 1);
            TransformMessages.transform(writer, nowNs, s.exported.frameId(), s.exported.transformChild(), odometry.xM,
                    odometry.yM, odometry.yawRad);
            tf.publish(writer.buffer(), writer.size(), nowNs);
        }
    }

    private void publishStatistics(MetricsMessage message, long windowStopWorldNs) throws ZenohException {
        metricsCodec.encode(header, message, writer);
        statisticsPublisher.publish(writer.buffer(), writer.size(), message.windowStopNs);
    }

    private void publishStaticTransforms() throws ZenohException {
        if (tfStatic != null) {
            long nowNs = epoch.epochNanos();
            TransformMessages.write(writer, nowNs, staticTransforms);
            tfStatic.publish(writer.buffer(), writer.size(), nowNs);
        }
    }

    private void publishDiagnostics() throws ZenohException {
        array.clear();
        List<TaskInfo> tasks = monitor.tasks();
        for (TaskInfo task : tasks) {
            taskDiagnostics.fill(task, monitor.counters(task.index()), array.add());
        }
        for (String key : monitor.keyNames()) {
            keyStatus(key, array.add());
        }
        long nowNs = epoch.epochNanos();
        diagnosticCodec.encode(header.set(nowNs, ""), array, writer);
        diagnostics.publish(writer.buffer(), writer.size(), nowNs);
        arraysPublished++;
    }

    private void keyStatus(String key, DiagnosticStatus s) {
        FeedStats feed = monitor.feed(key);
        s.level = DiagnosticStatus.OK;
        s.name.append("rtaware: key ").append(key);
        s.hardwareId.append("rtaware");
        String topic = topicByKey.get(key);
        s.message.append(topic != null ? "published on " + topic : "no ROS 2 type: health only");
        TaskDiagnostics.value(s, "commits", Long.toString(feed.commits()));
        TaskDiagnostics.value(s, "rate_hz", TaskDiagnostics.format(feed.rateHz()));
        TaskDiagnostics.value(s, "producer", String.valueOf(monitor.producer(key)));
        TaskDiagnostics.value(s, "topic", topic != null ? topic : "");
    }

    /** @return the topics the keys are published on, by key name */
    public Map<String, String> topics() {
        return Map.copyOf(topicByKey);
    }

    /** @return diagnostic arrays published so far */
    public long diagnosticsPublished() {
        return arraysPublished;
    }

    /** @return {@code statistics_msgs/msg/MetricsMessage}s published so far on {@value #STATISTICS} */
    public long statisticsPublished() {
        return statistics.messagesPublished();
    }

    /**
     * @return records of the monitor the statistics could not count: dropped because the
     *     exporter's ring was full, or handed over after their second had been published
     */
    public long statisticsLost() {
        return feed.dropped() + statistics.lateRecords();
    }

    /** @return why the thread stopped early, or null */
    public String failure() {
        return failure;
    }

    /**
     * Stops the thread, publishes the statistics of every whole second not published yet and one
     * last health array, closes the session.
     */
    @Override
    public void close() throws ZenohException {
        loop.close();
        try {
            if (loop.isClosed() && failure == null) {
                feed.drainInto(statistics);
                statistics.finish(monitor.clock().nanos());
                publishDiagnostics();
            }
        } catch (ZenohException e) {
            throw e;
        } catch (IOException e) {
            throw new ZenohException(e.getMessage());
        } finally {
            context.close();
        }
    }
}
