package io.rtaware.record;

import io.rtaware.record.mcap.Compression;
import java.util.HashMap;
import java.util.Map;

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
    /** The ground-truth topic. */
    public static final String GROUND_TRUTH_TOPIC = "/ground_truth";

    private final Map<String, String> topics = new HashMap<>();
    private final Map<String, String> frames = new HashMap<>();
    private final Map<String, String> metadata = new HashMap<>();
    private Compression compression = Compression.ZSTD;
    private int valueSlots = 8192;
    private long valueBytesPerKey = 4L << 20;
    private int cycleSlots = 16384;
    private int eventSlots = 4096;

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
     * @param key a key name
     * @return its topic
     */
    public String topicOf(String key) {
        return topics.getOrDefault(key, DATA_PREFIX + key);
    }

    /**
     * @param key a key name
     * @return its header's frame id ({@code map} unless set)
     */
    public String frameOf(String key) {
        return frames.getOrDefault(key, "map");
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
