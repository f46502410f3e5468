package io.rtaware.record;

import io.rtaware.core.data.Key;
import io.rtaware.core.data.StateValue;
import io.rtaware.record.encode.ByteBuf;
import io.rtaware.record.encode.JsonStateCodec;
import io.rtaware.record.encode.StateFields;
import io.rtaware.record.encode.TimingTypes;
import io.rtaware.record.mcap.McapWriter;
import io.rtaware.ros2msg.Ros2Codec;
import io.rtaware.ros2msg.Ros2Header;
import io.rtaware.ros2msg.cdr.CdrWriter;
import io.rtaware.ros2msg.value.PlanarPose;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicLongArray;
import java.util.concurrent.locks.LockSupport;

/**
 * Records a run to an MCAP file without slowing the tasks it records.
 *
 * <p>Task threads call {@link #commit}, {@link #cycle} and {@link #event}: each copies what it
 * is given into a slot of a ring allocated at construction (one ring per key, one per task, one
 * for events) and returns: no lock, no allocation, no I/O. A full ring drops the record and
 * counts it. A writer thread of the recorder's own drains the rings, encodes (standard ROS 2
 * types as CDR, other values as JSON, timing as rtaware's CDR types) and writes chunks.
 *
 * <p>Channels: each recorded key on its topic ({@link RecordingPlan#topicOf}); for keys with a
 * ROS 2 type, the fields the ROS 2 message lacks on {@code /rtaware/state/<key>} as JSON (so a
 * value can be rebuilt exactly); one {@code /rtaware/timing/<task>} per task, one message per
 * cycle; {@code /rtaware/events}; {@code /ground_truth}. Log and publish time of every message
 * are the world time of its commit, cycle end or event.
 *
 * <p>{@link #finish()} drains everything, writes the summary and the footer: call it on every exit
 * path (the run's termination handler). Thread-safety: {@link #commit} for one key from one
 * thread at a time (its producer), {@link #cycle} for one task from one thread at a time,
 * {@link #event} and {@link #groundTruth} from any thread.
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
    private static final String[] OUTCOMES = {TimingTypes.OK, TimingTypes.MISS, TimingTypes.SKIPPED,
        TimingTypes.STALE, TimingTypes.ERROR};

    /** Event kinds of {@link #event}. */
    public static final byte DEADLINE_MISS = 0;
    /** An input older than its declared maximum age. */
    public static final byte EXPIRED_READ = 1;
    /** An adaptive period change. */
    public static final byte PERIOD_CHANGE = 2;
    /** A cycle threw. */
    public static final byte TASK_ERROR = 3;
    private static final String[] EVENT_KINDS = {"deadline_miss", "expired_read", "period_change", "task_error"};

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

    private static final long IDLE_PARK_NS = 1_000_000;
    private static final int CDR_CAPACITY = 2 << 20;

    private final Path file;
    private final McapWriter writer;
    private final KeyRing[] keys;
    private final CycleRing[] tasks;
    private final List<String> taskNames;
    private final List<String> keyNames;
    private final EventRing events;
    private final PoseRing truth;
    private final AtomicLong dropped = new AtomicLong();
    private final CdrWriter cdr = new CdrWriter(CDR_CAPACITY);
    private final ByteBuf json = new ByteBuf(1 << 16);
    private final Ros2Header header = new Ros2Header();
    private final Thread thread;
    private volatile boolean stopping;
    private volatile String failure;
    private boolean closed;
    private final Map<String, Map<String, String>> closingMetadata = new LinkedHashMap<>();
    private RecordingStats stats;

    /**
     * Creates the file, writes its schemas and channels, and starts the writer thread.
     *
     * @param file the MCAP file (created or truncated)
     * @param taskNames task names by task index
     * @param taskInputs each task's input key names, in the order {@link #cycle} gives their generations
     * @param keysByIndex every key by key index (the index {@link #commit} is called with); null
     *     entries are not recorded
     * @param plan topics, metadata, ring sizes, compression
     * @throws IOException if the file cannot be written
     */
    public RunRecorder(Path file, List<String> taskNames, List<List<String>> taskInputs, List<Key<?>> keysByIndex,
                       RecordingPlan plan) throws IOException {
        this.file = file;
        this.taskNames = List.copyOf(taskNames);
        List<String> names = new ArrayList<>();
        for (Key<?> k : keysByIndex) {
            names.add(k == null ? null : k.name());
        }
        this.keyNames = names;
        this.writer = new McapWriter(file, plan.compression(), McapWriter.DEFAULT_CHUNK_BYTES, "");
        try {
            writer.addMetadata("rtaware.run", plan.metadata());
            keys = new KeyRing[keysByIndex.size()];
            for (int i = 0; i < keys.length; i++) {
                Key<?> key = keysByIndex.get(i);
                if (key != null) {
                    keys[i] = new KeyRing(key, plan);
                }
            }
            int cycleSchema = writer.addSchema(TimingTypes.TASK_CYCLE.name(), "ros2msg",
                    TimingTypes.TASK_CYCLE.schemaText());
            tasks = new CycleRing[taskNames.size()];
            for (int t = 0; t < tasks.length; t++) {
                List<String> inputs = taskInputs.get(t);
                int channel = writer.addChannel(cycleSchema, RecordingPlan.TIMING_PREFIX + taskNames.get(t), "cdr",
                        Map.of("task", taskNames.get(t), "inputs", String.join(",", inputs), SEQUENCE, SEQUENCE_CYCLE));
                tasks[t] = new CycleRing(channel, inputs.size(), plan.cycleSlots());
            }
            int eventSchema = writer.addSchema(TimingTypes.MONITOR_EVENT.name(), "ros2msg",
                    TimingTypes.MONITOR_EVENT.schemaText());
            events = new EventRing(writer.addChannel(eventSchema, RecordingPlan.EVENTS_TOPIC, "cdr", Map.of()),
                    plan.eventSlots());
            Ros2Codec<?> poseCodec = RosCodecs.forType(PlanarPose.class);
            int poseSchema = writer.addSchema(poseCodec.type().name(), "ros2msg", poseCodec.type().schemaText());
            truth = new PoseRing(writer.addChannel(poseSchema, RecordingPlan.GROUND_TRUTH_TOPIC, "cdr",
                    Map.of("frame_id", "map")), poseCodec, plan.valueSlots() * 8);
        } catch (IOException | RuntimeException e) {
            writer.close();
            throw e;
        }
        thread = new Thread(this::writeLoop, "rtaware-recorder");
        thread.setDaemon(true);
        thread.start();
    }

    /** @return the file being written */
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
        KeyRing ring = keyIndex < keys.length ? keys[keyIndex] : null;
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
     * Hands a ground-truth pose to the recorder (the sampling thread).
     *
     * @param timeNs world time of the sample
     * @param xM x in metres
     * @param yM y in metres
     * @param yawRad heading in radians
     */
    public void groundTruth(long timeNs, double xM, double yM, double yawRad) {
        if (!truth.offer(timeNs, xM, yM, yawRad)) {
            dropped.incrementAndGet();
        }
    }

    // ---------------------------------------------------------------- writer thread

    private void writeLoop() {
        try {
            while (true) {
                boolean finishing = stopping;
                int written = drainAll();
                if (written == 0) {
                    if (finishing) {
                        return;
                    }
                    LockSupport.parkNanos(IDLE_PARK_NS);
                }
            }
        } catch (IOException | RuntimeException e) {
            failure = e.toString();
            // Keep the rings moving so producers only drop, never block.
            while (!stopping) {
                discardAll();
                LockSupport.parkNanos(IDLE_PARK_NS);
            }
        }
    }

    private int drainAll() throws IOException {
        int n = 0;
        for (KeyRing k : keys) {
            if (k != null) {
                n += k.drain();
            }
        }
        for (CycleRing c : tasks) {
            n += c.drain();
        }
        n += events.drain();
        n += truth.drain();
        return n;
    }

    private void discardAll() {
        for (KeyRing k : keys) {
            if (k != null) {
                k.index.discardAll();
            }
        }
        for (CycleRing c : tasks) {
            c.index.discardAll();
        }
        events.discard();
        truth.index.discardAll();
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
     * file (summary, footer). Idempotent.
     *
     * @return what was recorded
     */
    public synchronized RecordingStats finish() {
        if (closed) {
            return stats;
        }
        closed = true;
        stopping = true;
        LockSupport.unpark(thread);
        try {
            thread.join();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        String error = failure;
        try {
            for (Map.Entry<String, Map<String, String>> m : closingMetadata.entrySet()) {
                writer.addMetadata(m.getKey(), m.getValue());
            }
            writer.close();
        } catch (IOException e) {
            error = error == null ? e.toString() : error;
        }
        stats = new RecordingStats(file.toString(), writer.messageCount(), writer.fileBytes(), dropped.get(), error);
        return stats;
    }

    // ---------------------------------------------------------------- rings

    /** Single-producer ring of one key's committed values. */
    /**
     * The positions of a single-producer, single-consumer ring of {@code capacity} slots: the
     * producer claims the next position and publishes it once the slot is written; the writer
     * thread reads the published ones and hands them back. Positions only grow.
     */
    private static final class RingIndex {
        private final AtomicLong head = new AtomicLong();
        private final AtomicLong tail = new AtomicLong();
        private final int capacity;

        RingIndex(int capacity) {
            this.capacity = capacity;
        }

        /** Producer: the next position to write, or -1 when every slot is still unread. */
        long claim() {
            long h = head.get();
            return h - tail.get() >= capacity ? -1 : h;
        }

        /** Producer: the slot at {@code position} is written. */
        void publish(long position) {
            head.lazySet(position + 1);
        }

        int slot(long position) {
            return (int) (position % capacity);
        }

        /** Consumer: the first position not yet read. */
        long consumed() {
            return tail.get();
        }

        /** Consumer: one past the last position published. */
        long published() {
            return head.get();
        }

        /** Consumer: positions before {@code position} are read and their slots free. */
        void consumedUpTo(long position) {
            tail.lazySet(position);
        }

        /** Consumer: drops every published position unread. */
        void discardAll() {
            tail.lazySet(head.get());
        }
    }

    private final class KeyRing {
        final StateValue<?>[] slots;
        final long[] times;
        final long[] generations;
        final RingIndex index;
        final int channel;
        final int stateChannel;
        @SuppressWarnings("rawtypes")
        final Ros2Codec ros;
        final JsonStateCodec jsonCodec;
        final String frame;

        KeyRing(Key<?> key, RecordingPlan plan) throws IOException {
            StateValue<?> first = key.newBuffer();
            long valueBytes = StateFields.of(key.type()).estimateBytes(first);
            int n = (int) Math.max(Math.min(8, plan.valueSlots()),
                    Math.min(plan.valueSlots(), plan.valueBytesPerKey() / Math.max(1, valueBytes)));
            slots = new StateValue<?>[n];
            slots[0] = first;
            for (int i = 1; i < n; i++) {
                slots[i] = key.newBuffer();
            }
            times = new long[n];
            generations = new long[n];
            index = new RingIndex(n);
            frame = plan.frameOf(key.name());
            ros = RosCodecs.forType(key.type());
            String topic = plan.topicOf(key.name());
            if (ros != null) {
                int schema = writer.addSchema(ros.type().name(), "ros2msg", ros.type().schemaText());
                channel = writer.addChannel(schema, topic, "cdr", Map.of("key", key.name(), "frame_id", frame,
                        SEQUENCE, SEQUENCE_GENERATION));
                jsonCodec = new JsonStateCodec(key.type(), true);
                int stateSchema = writer.addSchema("rtaware/state/" + key.type().getSimpleName(), "jsonschema",
                        jsonCodec.jsonSchema());
                stateChannel = writer.addChannel(stateSchema, RecordingPlan.STATE_PREFIX + key.name(), "json",
                        Map.of("key", key.name(), SEQUENCE, SEQUENCE_GENERATION));
            } else {
                jsonCodec = new JsonStateCodec(key.type(), false);
                int schema = writer.addSchema(key.type().getName(), "jsonschema", jsonCodec.jsonSchema());
                channel = writer.addChannel(schema, topic, "json", Map.of("key", key.name(), SEQUENCE,
                        SEQUENCE_GENERATION));
                stateChannel = 0;
            }
        }

        @SuppressWarnings({"unchecked", "rawtypes"})
        boolean offer(StateValue<?> value, long generation, long timeNs) {
            long h = index.claim();
            if (h < 0) {
                return false;
            }
            int s = index.slot(h);
            ((StateValue) slots[s]).copyFrom(value);
            times[s] = timeNs;
            generations[s] = generation;
            index.publish(h);
            return true;
        }

        @SuppressWarnings("unchecked")
        int drain() throws IOException {
            long t = index.consumed();
            long h = index.published();
            for (long i = t; i < h; i++) {
                int s = index.slot(i);
                long time = times[s];
                long generation = generations[s];
                if (ros != null) {
                    header.set(time, frame);
                    ros.encode(header, slots[s], cdr);
                    writer.writeMessage(channel, generation, time, time, cdr.buffer(), 0, cdr.size());
                    json.clear();
                    jsonCodec.encode(slots[s], json);
                    writer.writeMessage(stateChannel, generation, time, time, json.array(), 0, json.size());
                } else {
                    json.clear();
                    jsonCodec.encode(slots[s], json);
                    writer.writeMessage(channel, generation, time, time, json.array(), 0, json.size());
                }
                index.consumedUpTo(i + 1);
            }
            return (int) (h - t);
        }
    }

    /** Single-producer ring of one task's cycles. */
    private final class CycleRing {
        final int channel;
        final int inputs;
        final byte[] outcome;
        final long[] release;
        final long[] start;
        final long[] end;
        final long[] skipped;
        final long[] generations;
        final long[] numbers;
        /** Records offered so far, dropped ones included (producer thread only). */
        long offered;
        final RingIndex index;

        CycleRing(int channel, int inputs, int n) {
            this.channel = channel;
            this.inputs = inputs;
            outcome = new byte[n];
            release = new long[n];
            start = new long[n];
            end = new long[n];
            skipped = new long[n];
            numbers = new long[n];
            generations = new long[n * Math.max(1, inputs)];
            index = new RingIndex(n);
        }

        boolean offer(byte what, long r, long s0, long e, long skips, long[] gens) {
            long number = offered++;
            long h = index.claim();
            if (h < 0) {
                return false;
            }
            int s = index.slot(h);
            numbers[s] = number;
            outcome[s] = what;
            release[s] = r;
            start[s] = s0;
            end[s] = e;
            skipped[s] = skips;
            for (int i = 0; i < inputs; i++) {
                generations[s * inputs + i] = gens == null ? 0 : gens[i];
            }
            index.publish(h);
            return true;
        }

        int drain() throws IOException {
            long t = index.consumed();
            long h = index.published();
            for (long i = t; i < h; i++) {
                int s = index.slot(i);
                cdr.begin();
                cdr.writeInt64(release[s]);
                cdr.writeInt64(start[s]);
                cdr.writeInt64(end[s]);
                cdr.writeFloat64(Math.max(0, start[s] - release[s]) / 1e6);
                cdr.writeFloat64((end[s] - start[s]) / 1e6);
                cdr.writeString(OUTCOMES[outcome[s]]);
                cdr.writeInt64(skipped[s]);
                cdr.writeSequenceLength(inputs);
                for (int k = 0; k < inputs; k++) {
                    cdr.writeInt64(generations[s * inputs + k]);
                }
                writer.writeMessage(channel, numbers[s], end[s], end[s], cdr.buffer(), 0, cdr.size());
                index.consumedUpTo(i + 1);
            }
            return (int) (h - t);
        }
    }

    /** Multi-producer ring of monitor events: a slot is claimed by one atomic increment. */
    private final class EventRing {
        final int channel;
        final int n;
        final AtomicLongArray published;
        final byte[] kind;
        final int[] task;
        final long[] time;
        final long[] a;
        final long[] b;
        final boolean[] flag;
        final String[] key;
        final Object[] detail;
        final AtomicLong claimed = new AtomicLong();
        long next;

        EventRing(int channel, int n) {
            this.channel = channel;
            this.n = n;
            published = new AtomicLongArray(n);
            for (int i = 0; i < n; i++) {
                published.set(i, -1);
            }
            kind = new byte[n];
            task = new int[n];
            time = new long[n];
            a = new long[n];
            b = new long[n];
            flag = new boolean[n];
            key = new String[n];
            detail = new Object[n];
        }

        boolean offer(byte k, int t, long timeNs, long x, long y, boolean f, String keyName, Object d) {
            long c;
            do {
                c = claimed.get();
                if (c - consumed.get() >= n) {
                    return false;
                }
            } while (!claimed.compareAndSet(c, c + 1));
            int s = (int) (c % n);
            kind[s] = k;
            task[s] = t;
            time[s] = timeNs;
            a[s] = x;
            b[s] = y;
            flag[s] = f;
            key[s] = keyName;
            detail[s] = d;
            published.set(s, c);
            return true;
        }

        final AtomicLong consumed = new AtomicLong();

        int drain() throws IOException {
            int count = 0;
            while (true) {
                int s = (int) (next % n);
                if (published.get(s) != next) {
                    return count;
                }
                byte k = kind[s];
                cdr.begin();
                cdr.writeString(EVENT_KINDS[k]);
                cdr.writeString(taskNames.get(task[s]));
                cdr.writeString(key[s] == null ? "" : key[s]);
                cdr.writeInt64(time[s]);
                cdr.writeInt64(k == DEADLINE_MISS ? a[s] : 0);
                cdr.writeInt64(k == DEADLINE_MISS ? b[s] : 0);
                cdr.writeBool(k == DEADLINE_MISS && flag[s]);
                cdr.writeInt64(k == EXPIRED_READ ? a[s] : 0);
                cdr.writeInt64(k == EXPIRED_READ ? b[s] : 0);
                cdr.writeInt64(k == PERIOD_CHANGE ? a[s] : 0);
                cdr.writeInt64(k == PERIOD_CHANGE ? b[s] : 0);
                cdr.writeString(detail[s] == null ? "" : detail[s].toString());
                writer.writeMessage(channel, time[s], time[s], cdr.buffer(), 0, cdr.size());
                detail[s] = null;
                key[s] = null;
                next++;
                consumed.lazySet(next);
                count++;
            }
        }

        void discard() {
            while (published.get((int) (next % n)) == next) {
                detail[(int) (next % n)] = null;
                next++;
                consumed.lazySet(next);
            }
        }
    }

    /** Single-producer ring of ground-truth poses. */
    private final class PoseRing {
        final int channel;
        @SuppressWarnings("rawtypes")
        final Ros2Codec codec;
        final long[] time;
        final double[] x;
        final double[] y;
        final double[] yaw;
        final PlanarPose pose = new PlanarPose();
        final RingIndex index;

        PoseRing(int channel, Ros2Codec<?> codec, int n) {
            this.channel = channel;
            this.codec = codec;
            time = new long[n];
            x = new double[n];
            y = new double[n];
            yaw = new double[n];
            index = new RingIndex(n);
        }

        synchronized boolean offer(long t, double px, double py, double pyaw) {
            long h = index.claim();
            if (h < 0) {
                return false;
            }
            int s = index.slot(h);
            time[s] = t;
            x[s] = px;
            y[s] = py;
            yaw[s] = pyaw;
            index.publish(h);
            return true;
        }

        @SuppressWarnings("unchecked")
        int drain() throws IOException {
            long t = index.consumed();
            long h = index.published();
            for (long i = t; i < h; i++) {
                int s = index.slot(i);
                pose.set(x[s], y[s], yaw[s]);
                header.set(time[s], "map");
                codec.encode(header, pose, cdr);
                writer.writeMessage(channel, time[s], time[s], cdr.buffer(), 0, cdr.size());
                index.consumedUpTo(i + 1);
            }
            return (int) (h - t);
        }
    }
}
