package io.rtaware.record;

import io.rtaware.core.data.Key;
import io.rtaware.core.data.StateValue;
import io.rtaware.record.encode.TimingTypes;
import io.rtaware.record.mcap.McapWriter;
import io.rtaware.ros2msg.PoseStampedCodec;
import io.rtaware.ros2msg.RobotTopics;
import io.rtaware.ros2msg.Ros2Types;
import io.rtaware.ros2msg.TransformMessages;
import io.rtaware.ros2msg.cdr.CdrWriter;
import io.rtaware.ros2msg.statistics.TimingStatistics;
import io.rtaware.ros2msg.value.PlanarTransform;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.atomic.AtomicLong;

/**
 * Records a run to an MCAP file without slowing the tasks it records: the producers' side of
 * the recorder. Its parts, one job each: the rings ({@link CommitRing}, {@link CycleRing},
 * {@link EventRing}, {@link GroundTruthRing}, thin uses of the rings of
 * {@link io.rtaware.record.ring} whose types name their producers), the channel layout and encoding
 * ({@link KeyChannels}, {@link TimingEncoder}), and the writer thread ({@link RecorderWriterThread}).
 *
 * <p>Task threads call {@link #commit}, {@link #cycle} and {@link #event}: each copies what it
 * is given into a slot of a ring allocated at construction and returns: no lock, no allocation,
 * no I/O. A full ring drops the record and counts it.
 *
 * <p>The file follows the MCAP {@code ros2} profile ({@link Ros2Channels}): every channel CDR
 * with a {@code ros2msg} schema, QoS and type hash per channel, and the {@code rosbag2}
 * metadata record. Channels: each recorded key on its topic ({@link RecordingPlan#topicOf}) as
 * its standard ROS 2 type, or else as an {@code rtaware_msgs/msg/StateJson}; for keys with a
 * ROS 2 type, the fields the ROS 2 message lacks on {@code /rtaware/state/<key>} as a StateJson
 * (so a value can be rebuilt exactly); one {@code /rtaware/timing/<task>} per task
 * ({@code rtaware_msgs/msg/TaskCycle}), one message per cycle; {@code /rtaware/events}
 * ({@code rtaware_msgs/msg/MonitorEvent}); {@code /ground_truth} if the plan declares it;
 * {@code /tf_static} and {@code /tf} as the plan names them; {@code /clock} when the world runs
 * on simulated time ({@link RecordingPlan#clock}); {@code /statistics}
 * ({@code statistics_msgs/msg/MetricsMessage}, {@link TimingStatistics}): ROS 2's topic statistics
 * of every task and key, one message per second of world time per metric, computed on the writer
 * thread from the commits and cycles it writes, logged at the end of their window. Log and
 * publish time of every message are the world time of its commit, cycle end or event (a
 * statistics window's end) plus the plan's log-time offset (Unix-epoch ns),
 * and messages are written in log-time order through a reorder window
 * ({@link LogTimeOrderedSink}). A plan's {@link RecordingTap} (a live server) is told of every
 * channel and handed every message through a reorder window of its own ({@link TappedSink}): in
 * log-time order on every channel, at most the plan's reorder window of world time after the
 * writer thread encoded it; without a file the recorder works for the tap alone.
 *
 * <p>{@link #finish()} drains everything, writes the summary and the footer: call it on every exit
 * path (the run's termination handler). Thread-safety, as the rings' types say:
 * {@link #commit} for one key from one thread at a time (its producer), {@link #cycle} for one
 * task from one thread at a time, {@link #groundTruth} from one thread at a time (the sampler),
 * {@link #event} from any thread.
 */
public final class RunRecorder {

    /** Outcome codes of {@link #cycle}. */
    public static final byte OK = 0;
    /** A cycle that missed its deadline. */
    public static final byte MISS = 1;
    /** Releases skipped (one record for a run of them). */
    public static final byte SKIPPED = 2;
    /** A cycle without new input. */
    public static final byte STALE = 3;
    /** A cycle that threw. */
    public static final byte ERROR = 4;

    /** Event kinds of {@link #event}. */
    public static final byte DEADLINE_MISS = 0;
    /** An input older than its declared maximum age. */
    public static final byte EXPIRED_READ = 1;
    /** An adaptive period change. */
    public static final byte PERIOD_CHANGE = 2;
    /** A cycle threw. */
    public static final byte TASK_ERROR = 3;
    /** Event kind of a log line of the run's own ({@link #log}): on {@code /rosout} only. */
    static final byte LOG_LINE = 4;
    /** {@code rcl_interfaces/msg/Log} severity: information. */
    public static final byte INFO = 20;
    /** {@code rcl_interfaces/msg/Log} severity: a warning (deadline misses, expired reads). */
    public static final byte WARN = 30;
    /** {@code rcl_interfaces/msg/Log} severity: an error (task errors, collisions). */
    public static final byte ERROR_LEVEL = 40;
    /** {@code rcl_interfaces/msg/Log} severity: fatal (what ends a run for safety). */
    public static final byte FATAL = 50;
    /** The health topic: a status per task once a second ({@link RecordingPlan#health}). */
    public static final String DIAGNOSTICS_TOPIC = "/diagnostics";
    /** The log topic, as ROS 2 nodes log. */
    public static final String ROSOUT_TOPIC = "/rosout";

    /**
     * Channel metadata naming what a message's MCAP sequence number counts: on key channels
     * ({@value #SEQUENCE_GENERATION}) the commit's generation, on timing channels
     * ({@value #SEQUENCE_CYCLE}) the record's number among the task's records from 0, dropped ones
     * included; so a reader sees exactly which commits and cycles a recording lacks.
     */
    public static final String SEQUENCE = "sequence";
    /** {@link #SEQUENCE} of key channels. */
    public static final String SEQUENCE_GENERATION = "generation";
    /** {@link #SEQUENCE} of timing channels. */
    public static final String SEQUENCE_CYCLE = "cycle";
    /**
     * The metadata record, written when the file is finished, of what the file's
     * {@code /statistics} could not count: {@code windows} published, {@code late_records}
     * (records that reached the writer after their window was written) and {@code unmatched_ages}
     * (ages whose commit was dropped or missing), with {@code window_ns}.
     */
    public static final String STATISTICS_METADATA = "rtaware.statistics";
    /** The MCAP profile of recordings: every channel CDR with a {@code ros2msg} schema. */
    public static final String PROFILE = "ros2";
    /** Most messages the reorder window holds. */
    private static final int REORDER_SLOTS = 1 << 16;
    /** Most message bytes the reorder window holds. */
    private static final long REORDER_BYTES = 64L << 20;

    private final Path file;
    private final McapWriter writer;
    private final CommitRing[] keys;
    private final CycleRing[] tasks;
    private final List<String> keyNames;
    private final EventRing events;
    private final GroundTruthRing truth;
    private final AtomicLong dropped = new AtomicLong();
    private final RecorderWriterThread thread;
    private final Ros2Channels layout;
    /** The file's sink, or null without a file. */
    private final LogTimeOrderedSink ordered;
    /** {@code /statistics}, or null for a recording of no task and no key. */
    private final StatisticsChannel statistics;
    /** The tap's and the file's sinks, or null without a tap. */
    private final TappedSink tapped;
    /** Where the writer thread writes: the file's sink, the tap's, or both. */
    private final MessageSink sink;
    private boolean closed;
    private final Map<String, Map<String, String>> closingMetadata = new LinkedHashMap<>();
    private RecordingStats stats;

    /**
     * Creates the file, writes its schemas and channels, and starts the writer thread.
     *
     * @param file the MCAP file (created or truncated), or null to record for the plan's
     *     {@link RecordingPlan#tap} alone
     * @param taskNames task names by task index
     * @param taskInputs each task's input key names, in the order {@link #cycle} gives their generations
     * @param keysByIndex every key by key index (the index {@link #commit} is called with); null
     *     entries are not recorded
     * @param plan topics, metadata, ring sizes, compression
     * @throws IOException if the file cannot be written
     */
    public RunRecorder(Path file, List<String> taskNames, List<List<String>> taskInputs, List<Key<?>> keysByIndex,
                       RecordingPlan plan) throws IOException {
        this(file == null ? null : new McapWriter(file, plan.compression(), McapWriter.DEFAULT_CHUNK_BYTES, PROFILE),
                file, taskNames, taskInputs, keysByIndex, plan);
    }

    /**
     * Records into a writer of the caller's (e.g. over a channel that fails as a full disk does).
     *
     * @param writer the MCAP writer (closed by {@link #finish()}, or here if this fails), or null to
     *     record for the plan's {@link RecordingPlan#tap} alone
     * @param file the file written, for the statistics (null without a writer)
     * @param taskNames task names by task index
     * @param taskInputs each task's input key names, in the order {@link #cycle} gives their generations
     * @param keysByIndex every key by key index; null entries are not recorded
     * @param plan topics, metadata, ring sizes, log-time offset, reorder window
     * @throws IOException if the schemas and channels cannot be written
     */
    public RunRecorder(McapWriter writer, Path file, List<String> taskNames, List<List<String>> taskInputs,
                       List<Key<?>> keysByIndex, RecordingPlan plan) throws IOException {
        if (writer == null && plan.tap() == null) {
            throw new IllegalArgumentException("a recording needs a file, a tap or both");
        }
        this.file = writer == null ? null : file;
        this.writer = writer;
        List<String> names = new ArrayList<>();
        for (Key<?> k : keysByIndex) {
            names.add(k == null ? null : k.name());
        }
        this.keyNames = names;
        List<RecorderRing> rings = new ArrayList<>();
        layout = new Ros2Channels(writer, plan.tap());
        ordered = writer == null ? null : new LogTimeOrderedSink(writer::writeMessage, false, plan.logTimeOffsetNs(),
                plan.reorderWindowNs(), REORDER_SLOTS, REORDER_BYTES);
        tapped = plan.tap() == null ? null : new TappedSink(TappedSink.forTap(plan.tap(), plan.logTimeOffsetNs(),
                plan.reorderWindowNs(), REORDER_SLOTS, REORDER_BYTES), ordered);
        sink = tapped == null ? ordered : tapped;
        try {
            if (writer != null) {
                writer.addMetadata("rtaware.run", plan.metadata());
            }
            statistics = taskNames.isEmpty() && names.stream().allMatch(Objects::isNull) ? null
                    : new StatisticsChannel(layout.add(RecordingPlan.STATISTICS_TOPIC,
                            Ros2Types.METRICS_MESSAGE.name(), Ros2Types.METRICS_MESSAGE.schemaText(),
                            Ros2Types.METRICS_MESSAGE.typeHash(), Ros2Channels.Qos.RELIABLE_VOLATILE, Map.of()),
                            sink, taskNames, taskInputs, names, plan);
            TimingStatistics timing = statistics == null ? null : statistics.statistics();
            if (statistics != null && ordered != null) {
                ordered.holdAfter(statistics::nextLogTimeNs); // a second's statistics come after its messages
            }
            keys = new CommitRing[keysByIndex.size()];
            for (int i = 0; i < keys.length; i++) {
                Key<?> key = keysByIndex.get(i);
                if (key != null) {
                    keys[i] = new CommitRing(key, i, new KeyChannels(key, plan, layout), timing, plan.valueSlots(),
                            plan.valueBytesPerKey());
                    rings.add(keys[i]);
                }
            }
            tasks = new CycleRing[taskNames.size()];
            for (int t = 0; t < tasks.length; t++) {
                List<String> inputs = taskInputs.get(t);
                int channel = layout.add(RecordingPlan.TIMING_PREFIX + taskNames.get(t), TimingTypes.TASK_CYCLE.name(),
                        TimingTypes.TASK_CYCLE.schemaText(), TimingTypes.TASK_CYCLE.typeHash(),
                        Ros2Channels.Qos.RELIABLE_VOLATILE, Map.of("task", taskNames.get(t), "inputs", String.join(",", inputs), SEQUENCE, SEQUENCE_CYCLE));
                tasks[t] = new CycleRing(channel, t, timing, inputs.size(), plan.cycleSlots());
                rings.add(tasks[t]);
            }
            events = new EventRing(layout.add(RecordingPlan.EVENTS_TOPIC, TimingTypes.MONITOR_EVENT.name(),
                    TimingTypes.MONITOR_EVENT.schemaText(), TimingTypes.MONITOR_EVENT.typeHash(),
                    Ros2Channels.Qos.RELIABLE_VOLATILE, Map.of()),
                    layout.add(ROSOUT_TOPIC, Ros2Types.LOG.name(), Ros2Types.LOG.schemaText(), Ros2Types.LOG.typeHash(),
                            Ros2Channels.Qos.ROSOUT, Map.of()),
                    List.copyOf(taskNames), plan.eventSlots(), plan.logTimeOffsetNs());
            rings.add(events);
            if (plan.health() != null) {
                rings.add(new HealthRing(plan.health(), layout.add(DIAGNOSTICS_TOPIC, Ros2Types.DIAGNOSTIC_ARRAY.name(),
                        Ros2Types.DIAGNOSTIC_ARRAY.schemaText(), Ros2Types.DIAGNOSTIC_ARRAY.typeHash(),
                        Ros2Channels.Qos.RELIABLE_VOLATILE, Map.of()), plan.worldStartNs(), plan.logTimeOffsetNs()));
            }
            if (plan.hasGroundTruth()) {
                PoseStampedCodec poseCodec = new PoseStampedCodec();
                boolean transforms = !plan.staticTransforms().isEmpty();
                int truthTf = transforms ? layout.add(RobotTopics.TF, Ros2Types.TF_MESSAGE.name(),
                        Ros2Types.TF_MESSAGE.schemaText(), Ros2Types.TF_MESSAGE.typeHash(), Ros2Channels.Qos.TF,
                        Map.of()) : 0;
                truth = new GroundTruthRing(layout.add(RobotTopics.GROUND_TRUTH, poseCodec.type().name(),
                        poseCodec.type().schemaText(), poseCodec.type().typeHash(), Ros2Channels.Qos.RELIABLE_VOLATILE,
                        Map.of("frame_id", RobotTopics.WORLD_FRAME)), truthTf, poseCodec, plan.valueSlots() * 8, plan.logTimeOffsetNs());
                rings.add(truth);
            } else {
                truth = null;
            }
            if (statistics != null) {
                rings.add(statistics); // last in each pass: it publishes the windows the pass completed
            }
        } catch (IOException | RuntimeException e) {
            closeIfAny(writer);
            throw e;
        }
        try {
            if (plan.clockPeriodNs() > 0 && ordered != null) { // /clock is for files; a tap alone follows live time
                int clock = layout.add(RobotTopics.CLOCK, Ros2Types.CLOCK.name(), Ros2Types.CLOCK.schemaText(),
                        Ros2Types.CLOCK.typeHash(), Ros2Channels.Qos.CLOCK, Map.of());
                ordered.clock(new ClockTicks(writer, clock, plan.worldStartNs(), plan.clockPeriodNs(),
                        plan.logTimeOffsetNs()));
            }
            writeStaticTransforms(plan);
        } catch (IOException | RuntimeException e) {
            closeIfAny(writer);
            throw e;
        }
        thread = new RecorderWriterThread(rings, sink);
        thread.start();
    }

    /** Writes {@code /tf_static} once, at the recording's start (before the writer thread runs). */
    private void writeStaticTransforms(RecordingPlan plan) throws IOException {
        List<PlanarTransform> all = plan.staticTransforms();
        if (all.isEmpty()) {
            return;
        }
        int channel = layout.add(RobotTopics.TF_STATIC, Ros2Types.TF_MESSAGE.name(),
                Ros2Types.TF_MESSAGE.schemaText(), Ros2Types.TF_MESSAGE.typeHash(),
                Ros2Channels.Qos.RELIABLE_TRANSIENT_LOCAL, Map.of());
        CdrWriter cdr = new CdrWriter(4096);
        TransformMessages.write(cdr, plan.logTimeOffsetNs() + plan.worldStartNs(), all);
        sink.write(channel, 0, plan.worldStartNs(), plan.worldStartNs(), cdr.buffer(), 0, cdr.size());
    }

    /** Closes the writer, if there is one. */
    private static void closeIfAny(McapWriter writer) throws IOException {
        if (writer != null) {
            writer.close();
        }
    }

    /** @return the file being written, or null when recording for a tap alone */
    public Path file() {
        return file;
    }

    /** @return key names by key index (null for keys not recorded) */
    List<String> keyNames() {
        return keyNames;
    }

    // ---------------------------------------------------------------- producers (task threads)

    /**
     * Hands a committed value to the recorder (the producer's thread, right after the commit).
     * Copies it into a free slot of the key's ring; drops and counts it if there is none.
     *
     * @param keyIndex the key's index
     * @param generation the new generation
     * @param timeNs world time of the commit
     * @param value the value committed (read only during the call)
     */
    public void commit(int keyIndex, long generation, long timeNs, StateValue<?> value) {
        CommitRing ring = keyIndex < keys.length ? keys[keyIndex] : null;
        if (ring != null && !ring.offer(value, generation, timeNs)) {
            dropped.incrementAndGet();
        }
    }

    /**
     * Hands a finished cycle (or a run of skipped releases) to the recorder (the task's thread).
     *
     * @param taskIndex the task's index
     * @param outcome {@link #OK}, {@link #MISS}, {@link #SKIPPED}, {@link #STALE} or {@link #ERROR}
     * @param releaseNs scheduled release
     * @param startNs start
     * @param endNs end
     * @param skippedReleases releases skipped (outcome {@link #SKIPPED})
     * @param inputGenerations generation of each input read, in the task's input order (null if none)
     */
    public void cycle(int taskIndex, byte outcome, long releaseNs, long startNs, long endNs, long skippedReleases,
                      long[] inputGenerations) {
        if (!tasks[taskIndex].offer(outcome, releaseNs, startNs, endNs, skippedReleases, inputGenerations)) {
            dropped.incrementAndGet();
        }
    }

    /**
     * Hands a monitor event to the recorder (any thread).
     *
     * @param kind {@link #DEADLINE_MISS}, {@link #EXPIRED_READ}, {@link #PERIOD_CHANGE} or {@link #TASK_ERROR}
     * @param taskIndex the task
     * @param timeNs world time of the event
     * @param a release (miss), age (expired read), old period (period change)
     * @param b deadline (miss), maximum age (expired read), new period (period change)
     * @param flag still running (miss)
     * @param key the input's key name (expired read), else null
     * @param detail an object whose {@code toString()} the writer thread records (error, period change), or null
     */
    public void event(byte kind, int taskIndex, long timeNs, long a, long b, boolean flag, String key, Object detail) {
        if (!events.offer(kind, taskIndex, timeNs, a, b, flag, key, detail)) {
            dropped.incrementAndGet();
        }
    }

    /**
     * Hands a log line of the run's own to the recorder (any thread), written on {@code /rosout}
     * beside the monitor's events in words: what the command saw happen to the robot (a
     * collision, a near miss, a safety stop). Allocates nothing here; the writer thread encodes it.
     *
     * @param level {@link #INFO}, {@link #WARN}, {@link #ERROR_LEVEL} or {@link #FATAL}
     * @param timeNs world time of what it says
     * @param name the logger's name, e.g. {@code safety}
     * @param text the line
     */
    public void log(byte level, long timeNs, String name, String text) {
        if (!events.offerLine(level, timeNs, name, text)) {
            dropped.incrementAndGet();
        }
    }

    /**
     * Hands a ground-truth pose to the recorder (one thread at a time: the sampler); ignored
     * unless the plan declared ground truth ({@link RecordingPlan#withGroundTruth}).
     *
     * @param timeNs world time of the sample
     * @param xM x in metres
     * @param yM y in metres
     * @param yawRad heading in radians
     */
    public void groundTruth(long timeNs, double xM, double yM, double yawRad) {
        if (truth != null && !truth.offer(timeNs, xM, yM, yawRad)) {
            dropped.incrementAndGet();
        }
    }

    /**
     * Adds a metadata record written when the file is finished, for what is known only at the end
     * of a run (its conditions, {@code rtaware.conditions}). Call before {@link #finish()}.
     *
     * @param name the record's name
     * @param entries its entries
     */
    public synchronized void closingMetadata(String name, Map<String, String> entries) {
        closingMetadata.put(name, Map.copyOf(entries));
    }

    /**
     * Stops the writer thread after it has written everything handed over, then finishes the
     * file (summary, footer). Idempotent. A write that failed (a full disk) leaves the file
     * incomplete: the statistics then say why and count only the messages in whole chunks.
     *
     * @return what was recorded
     */
    public synchronized RecordingStats finish() {
        if (closed) {
            return stats;
        }
        closed = true;
        String error = thread.stopAndJoin();
        try {
            if (error == null && statistics != null) {
                statistics.finish();
            }
            if (error == null && tapped != null) {
                tapped.flush();
            }
            if (error == null && writer != null) {
                ordered.flush();
                layout.writeBagMetadata(file.getFileName() == null ? file.toString() : file.getFileName().toString());
                if (statistics != null) {
                    writer.addMetadata(STATISTICS_METADATA, statistics.metadata());
                }
                for (Map.Entry<String, Map<String, String>> m : closingMetadata.entrySet()) {
                    writer.addMetadata(m.getKey(), m.getValue());
                }
            }
            closeIfAny(writer);
        } catch (IOException e) {
            error = error == null ? (e.getMessage() == null ? e.toString() : e.getMessage()) : error;
        }
        if (writer == null) {
            stats = new RecordingStats(null, 0, 0, dropped.get(), 0, error);
            return stats;
        }
        long messages = error == null ? writer.messageCount() : writer.durableMessageCount();
        stats = new RecordingStats(file.toString(), messages, writer.fileBytes(), dropped.get(), ordered.outOfOrder(),
                error);
        return stats;
    }
}
