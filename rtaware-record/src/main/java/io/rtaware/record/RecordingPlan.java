package io.rtaware.record;

import io.rtaware.core.monitor.Monitor;
import io.rtaware.record.mcap.Compression;
import io.rtaware.ros2msg.RobotTopics;
import io.rtaware.ros2msg.value.PlanarTransform;
import java.time.Instant;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Where keys go in a recording: a topic per key name (keys without one are recorded on
 * {@code /rtaware/data/<key>}), the MCAP metadata describing the run, ring sizes and compression.
 * Mutable builder; configure before creating the recorder.
 */
public final class RecordingPlan {

    /** Prefix of the topics of keys without a topic of their own. */
    public static final String DATA_PREFIX = "/rtaware/data/";
    /** Prefix of the JSON topics carrying what a key's ROS 2 message lacks. */
    public static final String STATE_PREFIX = "/rtaware/state/";
    /** Prefix of the per-task timing topics. */
    public static final String TIMING_PREFIX = "/rtaware/timing/";
    /** The monitor events topic. */
    public static final String EVENTS_TOPIC = "/rtaware/events";
    /**
     * The topic statistics topic ({@code statistics_msgs/msg/MetricsMessage}, one message per
     * second of world time per task and key and metric, as ROS 2's topic statistics publish them;
     * every recording of a task or a key has it).
     */
    public static final String STATISTICS_TOPIC = "/statistics";
    /**
     * {@code rtaware.run} metadata: what was added to world time to make log times (Unix-epoch
     * ns of world time 0). Absent in recordings made before log times were epoch times (then 0).
     */
    public static final String LOG_TIME_OFFSET_NS = "log_time_offset_ns";
    /** {@code rtaware.run} metadata: the run's wall-clock start, Unix-epoch ns. */
    public static final String WALL_CLOCK_START_NS = "wall_clock_start_unix_ns";
    /** {@code rtaware.run} metadata: the world time at the run's wall-clock start, ns. */
    public static final String WORLD_START_NS = "world_start_ns";
    /** World time between {@code /clock} ticks the commands record: 10 ms (100 Hz). */
    public static final long CLOCK_PERIOD_NS = 10_000_000L;
    /**
     * {@code rtaware.run} metadata: {@value #STAMPS_MEASURED} when the ROS 2 headers of the
     * robot's scans and odometry are stamped at the time the robot measured them
     * ({@link #robotClockOriginNs(long)}); absent when every header is stamped with its commit's
     * time.
     */
    public static final String HEADER_STAMPS = "header_stamps";
    /** {@link #HEADER_STAMPS}: scans and odometry at the time the robot measured them. */
    public static final String STAMPS_MEASURED = "measured";
    /** {@code rtaware.run} metadata: the world time at which the robot's clock read 0, ns. */
    public static final String ROBOT_CLOCK_ORIGIN_NS = "robot_clock_origin_ns";

    private final Map<String, String> topics = new HashMap<>();
    private final Map<String, String> frames = new HashMap<>();
    private final Map<String, String> metadata = new HashMap<>();
    private final Set<String> latched = new HashSet<>();
    private long logTimeOffsetNs;
    private long worldStartNs;
    private boolean groundTruth;
    private final List<PlanarTransform> staticTransforms = new ArrayList<>();
    private final Map<String, String[]> transformsFrom = new HashMap<>();
    private long reorderWindowNs = 2_000_000_000L;
    private long robotClockOriginNs;
    private boolean robotClockKnown;
    private long clockPeriodNs;
    private Compression compression = Compression.ZSTD;
    private int valueSlots = 8192;
    private long valueBytesPerKey = 4L << 20;
    private int cycleSlots = 16384;
    private int eventSlots = 4096;
    private RecordingTap tap;
    private Monitor health;

    /**
     * @param key a key name
     * @param topic its topic, e.g. {@code /scan}
     * @param frameId the frame id of its header (ROS 2 types with a header)
     * @return this plan
     */
    public RecordingPlan topic(String key, String topic, String frameId) {
        topics.put(key, topic);
        frames.put(key, frameId);
        return this;
    }

    /**
     * Declares a key's topic latched: its publisher offers transient-local durability (a map),
     * so playback gives its last message to late subscribers.
     *
     * @param key a key name
     * @return this plan
     */
    public RecordingPlan latched(String key) {
        latched.add(key);
        return this;
    }

    /**
     * @param key a key name
     * @return true if its topic is latched
     */
    public boolean isLatched(String key) {
        return latched.contains(key);
    }

    /**
     * Declares that the run hands ground-truth poses to the recorder
     * ({@link RunRecorder#groundTruth}): only then does the file have a {@code /ground_truth}
     * channel (a bench has none, and declares no channel it never writes).
     *
     * @return this plan
     */
    public RecordingPlan withGroundTruth() {
        groundTruth = true;
        return this;
    }

    /** @return true if the recording has a {@code /ground_truth} channel */
    public boolean hasGroundTruth() {
        return groundTruth;
    }

    /**
     * Adds a transform to {@code /tf_static} (REP 105: e.g. {@code base_link} to {@code laser}).
     *
     * @param parent the parent frame
     * @param child the child frame
     * @param xM translation x in metres
     * @param yM translation y in metres
     * @param yawRad rotation about z in radians
     * @return this plan
     */
    public RecordingPlan staticTransform(String parent, String child, double xM, double yM, double yawRad) {
        staticTransforms.add(new PlanarTransform(parent, child, xM, yM, yawRad));
        return this;
    }

    /** @return the transforms of {@code /tf_static} */
    public List<PlanarTransform> staticTransforms() {
        return List.copyOf(staticTransforms);
    }

    /**
     * Publishes each commit of an odometry key as a transform on {@code /tf} as well (REP 105:
     * {@code odom} to {@code base_link}), stamped as its message.
     *
     * @param key an odometry key's name
     * @param parent the parent frame, e.g. {@code odom}
     * @param child the child frame, e.g. {@code base_link}
     * @return this plan
     */
    public RecordingPlan transformsFrom(String key, String parent, String child) {
        transformsFrom.put(key, new String[] {parent, child});
        return this;
    }

    /**
     * @param key a key name
     * @return the parent and child frame of the transforms its commits make, or null
     */
    public String[] transformsOf(String key) {
        String[] frames = transformsFrom.get(key);
        return frames == null ? null : frames.clone();
    }

    /**
     * Shows every channel and message of the recording to a tap as well (a live server), or, with
     * no file, to the tap alone ({@link RecordingListener#attach}).
     *
     * @param value the tap, or null for none
     * @return this plan
     */
    public RecordingPlan tap(RecordingTap value) {
        tap = value;
        return this;
    }

    /** @return the tap, or null */
    public RecordingTap tap() {
        return tap;
    }

    /**
     * Records {@code /diagnostics}: once a second of world time, a
     * {@code diagnostic_msgs/msg/DiagnosticArray} with each task's figures from the monitor's
     * counters, sampled by the writer thread ({@link RecordingListener#attach} sets it).
     *
     * @param monitor the monitor whose counters are sampled, or null for none
     * @return this plan
     */
    public RecordingPlan health(Monitor monitor) {
        health = monitor;
        return this;
    }

    /** @return the monitor whose health is recorded, or null */
    public Monitor health() {
        return health;
    }

    /**
     * Starts the recording's clock now: log times become Unix-epoch ns, the wall clock now plus
     * the world time since ({@link #logTimeOffsetNs}), with the wall-clock start and the world
     * time at it kept in the {@code rtaware.run} metadata so that readers recover world time.
     *
     * @param worldNowNs the world time now
     * @return this plan
     */
    public RecordingPlan startingNow(long worldNowNs) {
        Instant wallStart = Instant.now();
        long wallStartNs = wallStart.getEpochSecond() * 1_000_000_000L + wallStart.getNano();
        return metadata(WALL_CLOCK_START_NS, Long.toString(wallStartNs))
                .metadata(WORLD_START_NS, Long.toString(worldNowNs))
                .worldStartNs(worldNowNs)
                .logTimeOffsetNs(wallStartNs - worldNowNs);
    }

    /**
     * Declares where the robot's timestamps lie in world time, so that the ROS 2 headers of its
     * scans and odometry are stamped when it measured them ({@code LaserScan.serverTimeS}: the
     * scan as the robot stamps it, Player's laser timestamp or a ROS 2 header's stamp;
     * {@code Odometry.serverTimeS}: the pose's sample time) rather than when they were committed:
     * a timestamp of {@code t} seconds was taken at world time {@code originNs + t * 1e9}. Known
     * for the built-in simulator (the clock's reading at its time 0); without it every header is
     * stamped with its commit's time. Kept in the {@code rtaware.run} metadata as
     * {@value #HEADER_STAMPS} and {@value #ROBOT_CLOCK_ORIGIN_NS}.
     *
     * @param originNs the world time at which the robot's clock read 0
     * @return this plan
     */
    public RecordingPlan robotClockOriginNs(long originNs) {
        robotClockOriginNs = originNs;
        robotClockKnown = true;
        metadata.put(HEADER_STAMPS, STAMPS_MEASURED);
        metadata.put(ROBOT_CLOCK_ORIGIN_NS, Long.toString(originNs));
        return this;
    }

    /** @return true if {@link #robotClockOriginNs(long)} was given */
    public boolean robotClockKnown() {
        return robotClockKnown;
    }

    /** @return the world time at which the robot's clock read 0 (meaningful if {@link #robotClockKnown()}) */
    public long robotClockOriginNs() {
        return robotClockOriginNs;
    }

    /**
     * Records {@code /clock} ({@code rosgraph_msgs/msg/Clock}): the world runs on simulated time
     * (a time scale other than 1, or the simulator), so a consumer that follows {@code /clock}
     * (ROS's {@code use_sim_time}, {@code ros2 bag play --clock}) keeps the file's time. A tick
     * every {@code periodNs} of world time from the recording's start, each carrying its own log
     * time (the time every stamp and log time of the file is in), written in order with the
     * other messages up to the last of them.
     *
     * @param periodNs world time between ticks, positive
     * @return this plan
     */
    public RecordingPlan clock(long periodNs) {
        if (periodNs <= 0) {
            throw new IllegalArgumentException("/clock period must be positive, got " + periodNs + " ns");
        }
        clockPeriodNs = periodNs;
        return this;
    }

    /** @return world time between {@code /clock} ticks, or 0 for no {@code /clock} */
    public long clockPeriodNs() {
        return clockPeriodNs;
    }

    /**
     * @param nowNs the world time at the recording's start (when {@code /tf_static} is written)
     * @return this plan
     */
    public RecordingPlan worldStartNs(long nowNs) {
        worldStartNs = nowNs;
        return this;
    }

    /** @return the world time at the recording's start */
    public long worldStartNs() {
        return worldStartNs;
    }

    /**
     * Sets what is added to every world time to make the file's log times: the Unix-epoch time
     * in ns of world time 0 (the run's wall-clock start minus the world time at its start), so
     * log times are the Unix-epoch nanoseconds {@code ros2 bag} writes. Kept in the
     * {@code rtaware.run} metadata as {@value #LOG_TIME_OFFSET_NS}, so that readers recover world
     * time exactly. Default 0 (log time = world time).
     *
     * @param offsetNs the offset in ns
     * @return this plan
     */
    public RecordingPlan logTimeOffsetNs(long offsetNs) {
        logTimeOffsetNs = offsetNs;
        metadata.put(LOG_TIME_OFFSET_NS, Long.toString(offsetNs));
        return this;
    }

    /** @return what is added to world time to make log time */
    public long logTimeOffsetNs() {
        return logTimeOffsetNs;
    }

    /**
     * @param windowNs world time a message is held for earlier ones to arrive before it is
     *     written in log-time order (what arrives later is counted as out of order)
     * @return this plan
     */
    public RecordingPlan reorderWindowNs(long windowNs) {
        if (windowNs < 0) {
            throw new IllegalArgumentException("reorder window must not be negative, got " + windowNs);
        }
        reorderWindowNs = windowNs;
        return this;
    }

    /** @return the reorder window in world ns */
    public long reorderWindowNs() {
        return reorderWindowNs;
    }

    /**
     * @param key a key name
     * @return its topic
     */
    public String topicOf(String key) {
        return topics.getOrDefault(key, DATA_PREFIX + key);
    }

    /**
     * @param key a key name
     * @return its header's frame id ({@value RobotTopics#ODOM_FRAME} unless set: a controller
     *     without localization works in its odometry frame)
     */
    public String frameOf(String key) {
        return frames.getOrDefault(key, RobotTopics.ODOM_FRAME);
    }

    /**
     * @param name a metadata key of the {@code rtaware.run} metadata record
     * @param value its value
     * @return this plan
     */
    public RecordingPlan metadata(String name, String value) {
        metadata.put(name, value);
        return this;
    }

    /** @return the run's metadata */
    public Map<String, String> metadata() {
        return Map.copyOf(metadata);
    }

    /**
     * @param value chunk compression
     * @return this plan
     */
    public RecordingPlan compression(Compression value) {
        compression = value;
        return this;
    }

    /** @return chunk compression */
    public Compression compression() {
        return compression;
    }

    /**
     * @param commitsPerKey most slots of each key's commit ring (fewer for large values: see
     *     {@link #valueBytesPerKey()})
     * @param cyclesPerTask slots of each task's cycle ring
     * @param events slots of the event ring
     * @return this plan
     */
    public RecordingPlan slots(int commitsPerKey, int cyclesPerTask, int events) {
        if (commitsPerKey < 1 || cyclesPerTask < 1 || events < 1) {
            throw new IllegalArgumentException("ring sizes must be at least 1");
        }
        valueSlots = commitsPerKey;
        cycleSlots = cyclesPerTask;
        eventSlots = events;
        return this;
    }

    int valueSlots() {
        return valueSlots;
    }

    /**
     * @return memory a key's commit ring may take: a key whose value takes more than this
     *     divided by {@link #slots}'s count gets fewer slots (at least 8)
     */
    long valueBytesPerKey() {
        return valueBytesPerKey;
    }

    int cycleSlots() {
        return cycleSlots;
    }

    int eventSlots() {
        return eventSlots;
    }
}
