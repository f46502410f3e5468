package io.rtaware.core.trace;

import com.fasterxml.jackson.core.JsonEncoding;
import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonGenerator;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.monitor.MonitorListener;
import io.rtaware.core.monitor.PeriodChange;
import io.rtaware.core.monitor.TaskInfo;
import io.rtaware.core.time.Durations;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;

/**
 * Records a run's events for a timeline and writes them as Chrome trace event JSON (the format
 * Perfetto and chrome://tracing open):
 * <ul>
 *   <li>process 1 "tasks": one track (tid) per task, named after it; every cycle is a complete
 *   event ({@code ph: "X"}) from its start to its end, and its scheduled release an instant
 *   ({@code ph: "i"}, name {@code release}); deadline misses ({@code deadline miss}), stale runs
 *   ({@code stale run}), skipped releases ({@code skipped}, with the count), expired reads
 *   ({@code expired read}) and period changes ({@code period change}) are instants on the
 *   task's track;</li>
 *   <li>process 2 "data": one track per key, with an instant ({@code commit}) per commit.</li>
 * </ul>
 * Timestamps are microseconds of world time since the recorder was created.
 *
 * <p>Memory is bounded: events go into a ring buffer of {@code capacity} preallocated slots
 * (primitive arrays, nothing is allocated while recording). When it is full the oldest events
 * are overwritten; the file's {@code otherData} says how many were dropped.
 *
 * <p>Thread-safety: the recording methods may be called from any number of threads at once
 * (each event claims its slot with one atomic increment). {@link #write(Path)} must be called
 * after the monitor has stopped (e.g. from a termination handler), when no event is recorded.
 */
public final class TraceRecorder implements MonitorListener {

    /** Default ring capacity in events (about 29 MB). */
    public static final int DEFAULT_CAPACITY = 1 << 20;
    /**
     * Heap bytes one slot of the ring takes: a type byte, an int subject and three longs (the
     * arrays are allocated in full when the recorder is made).
     */
    public static final int BYTES_PER_EVENT = 1 + 4 + 3 * 8;

    private static final byte CYCLE = 1;
    private static final byte MISS = 2;
    private static final byte STALE = 3;
    private static final byte SKIPPED = 4;
    private static final byte COMMIT = 5;
    private static final byte EXPIRED = 6;
    private static final byte PERIOD = 7;

    private static final int TASKS_PID = 1;
    private static final int DATA_PID = 2;

    private final int capacity;
    private final long originNs;
    private final List<String> taskNames;
    private final List<String> keyNames;
    private final Map<String, Integer> keyIndex = new HashMap<>();
    private final byte[] type;
    private final int[] subject;
    private final long[] t0;
    private final long[] t1;
    private final long[] arg;
    private final AtomicLong sequence = new AtomicLong();

    /**
     * @param capacity ring size in events, at least 1
     * @param taskNames task names by task index
     * @param keyNames key names by key index
     * @param originNs world time that becomes timestamp 0
     */
    public TraceRecorder(int capacity, List<String> taskNames, List<String> keyNames, long originNs) {
        if (capacity < 1) {
            throw new IllegalArgumentException("trace capacity must be at least 1 event, got " + capacity);
        }
        this.capacity = capacity;
        this.originNs = originNs;
        this.taskNames = List.copyOf(taskNames);
        this.keyNames = List.copyOf(keyNames);
        for (int i = 0; i < keyNames.size(); i++) {
            keyIndex.put(keyNames.get(i), i);
        }
        type = new byte[capacity];
        subject = new int[capacity];
        t0 = new long[capacity];
        t1 = new long[capacity];
        arg = new long[capacity];
    }

    /**
     * The one call a command needs: creates a recorder sized for the monitor's tasks and keys,
     * with time 0 at the monitor clock's current time, and adds it as a listener.
     *
     * @param monitor a monitor that has not started yet
     * @param capacity ring size in events
     * @return the recorder; call {@link #write(Path)} after the monitor has stopped
     */
    public static TraceRecorder attach(Monitor monitor, int capacity) {
        TraceRecorder recorder = new TraceRecorder(capacity,
                monitor.tasks().stream().map(TaskInfo::name).toList(), monitor.keyNames(), monitor.clock().nanos());
        monitor.addListener(recorder);
        return recorder;
    }

    private void record(byte kind, int who, long a, long b, long c) {
        int slot = (int) (sequence.getAndIncrement() % capacity);
        type[slot] = kind;
        subject[slot] = who;
        t0[slot] = a;
        t1[slot] = b;
        arg[slot] = c;
    }

    @Override
    public void onCycle(TaskInfo task, long releaseNs, long startNs, long endNs) {
        record(CYCLE, task.index(), startNs, endNs, releaseNs);
    }

    @Override
    public void onDeadlineMiss(TaskInfo task, long releaseNs, long deadlineNs, long detectedNs, boolean stillRunning) {
        record(MISS, task.index(), detectedNs, deadlineNs, stillRunning ? 1 : 0);
    }

    @Override
    public void onStaleRun(TaskInfo task, long nowNs) {
        record(STALE, task.index(), nowNs, 0, 0);
    }

    @Override
    public void onSkippedReleases(TaskInfo task, long skipped, long nowNs) {
        record(SKIPPED, task.index(), nowNs, 0, skipped);
    }

    @Override
    public void onCommit(TaskInfo producer, int keyIndex, long generation, long nowNs) {
        record(COMMIT, keyIndex, nowNs, producer.index(), generation);
    }

    @Override
    public void onExpiredInput(TaskInfo task, String key, long ageNs, long maxAgeNs, long nowNs) {
        Integer k = keyIndex.get(key);
        record(EXPIRED, task.index(), nowNs, k == null ? -1 : k, ageNs);
    }

    @Override
    public void onPeriodChange(TaskInfo task, PeriodChange change, long nowNs) {
        record(PERIOD, task.index(), nowNs, change.fromPeriodNs(), change.toPeriodNs());
    }

    /** @return events recorded so far, including those overwritten */
    public long recorded() {
        return sequence.get();
    }

    /** @return events overwritten because the ring was full */
    public long dropped() {
        return Math.max(0, sequence.get() - capacity);
    }

    /** @return the ring size in events */
    public int capacity() {
        return capacity;
    }

    /**
     * Writes the trace file (parent folders are created). Call after the monitor has stopped.
     *
     * @param file the {@code .json} file to write
     * @throws IOException if writing fails
     */
    public void write(Path file) throws IOException {
        Path parent = file.toAbsolutePath().getParent();
        if (parent != null) {
            Files.createDirectories(parent);
        }
        try (OutputStream out = Files.newOutputStream(file);
             JsonGenerator g = new JsonFactory().createGenerator(out, JsonEncoding.UTF8)) {
            g.writeStartObject();
            g.writeStringField("displayTimeUnit", "ms");
            g.writeArrayFieldStart("traceEvents");
            writeMetadata(g);
            long end = sequence.get();
            for (long s = Math.max(0, end - capacity); s < end; s++) {
                writeEvent(g, (int) (s % capacity));
            }
            g.writeEndArray();
            g.writeObjectFieldStart("otherData");
            g.writeStringField("producer", "rtaware");
            g.writeNumberField("recorded_events", end);
            g.writeNumberField("dropped_events", dropped());
            g.writeNumberField("capacity_events", capacity);
            g.writeEndObject();
            g.writeEndObject();
        }
    }

    private static void metadata(JsonGenerator g, String name, int pid, int tid, String value) throws IOException {
        g.writeStartObject();
        g.writeStringField("name", name);
        g.writeStringField("ph", "M");
        g.writeNumberField("pid", pid);
        g.writeNumberField("tid", tid);
        g.writeObjectFieldStart("args");
        if (name.endsWith("sort_index")) {
            g.writeNumberField("sort_index", Integer.parseInt(value));
        } else {
            g.writeStringField("name", value);
        }
        g.writeEndObject();
        g.writeEndObject();
    }

    private void writeMetadata(JsonGenerator g) throws IOException {
        metadata(g, "process_name", TASKS_PID, 0, "tasks");
        metadata(g, "process_sort_index", TASKS_PID, 0, "0");
        for (int i = 0; i < taskNames.size(); i++) {
            metadata(g, "thread_name", TASKS_PID, i + 1, taskNames.get(i));
            metadata(g, "thread_sort_index", TASKS_PID, i + 1, Integer.toString(i));
        }
        metadata(g, "process_name", DATA_PID, 0, "data");
        metadata(g, "process_sort_index", DATA_PID, 0, "1");
        for (int i = 0; i < keyNames.size(); i++) {
            metadata(g, "thread_name", DATA_PID, i + 1, keyNames.get(i));
        }
    }

    private void writeEvent(JsonGenerator g, int slot) throws IOException {
        int who = subject[slot];
        switch (type[slot]) {
            case CYCLE -> {
                String name = taskNames.get(who);
                g.writeStartObject();
                g.writeStringField("name", name);
                g.writeStringField("cat", "cycle");
                g.writeStringField("ph", "X");
                g.writeNumberField("ts", us(t0[slot]));
                g.writeNumberField("dur", (t1[slot] - t0[slot]) / 1e3);
                g.writeNumberField("pid", TASKS_PID);
                g.writeNumberField("tid", who + 1);
                g.writeObjectFieldStart("args");
                g.writeNumberField("lateness_us", (t0[slot] - arg[slot]) / 1e3);
                g.writeEndObject();
                g.writeEndObject();
                instant(g, "release", "release", arg[slot], TASKS_PID, who + 1, null, 0);
            }
            case MISS -> instant(g, "deadline miss", "miss", t0[slot], TASKS_PID, who + 1,
                    arg[slot] == 1 ? "still_running_past_deadline_us" : "finished_past_deadline_us",
                    (t0[slot] - t1[slot]) / 1e3);
            case STALE -> instant(g, "stale run", "stale", t0[slot], TASKS_PID, who + 1, null, 0);
            case SKIPPED -> instant(g, "skipped", "miss", t0[slot], TASKS_PID, who + 1, "releases", arg[slot]);
            case COMMIT -> instant(g, "commit", "data", t0[slot], DATA_PID, who + 1, "generation", arg[slot]);
            case EXPIRED -> instant(g, "expired read" + (t1[slot] >= 0 ? " " + keyNames.get((int) t1[slot]) : ""),
                    "expired", t0[slot], TASKS_PID, who + 1, "age_us", arg[slot] / 1e3);
            case PERIOD -> instant(g, "period change " + Durations.format(t1[slot]) + " -> "
                    + Durations.format(arg[slot]), "adaptive", t0[slot], TASKS_PID, who + 1, "period_ms",
                    arg[slot] / 1e6);
            default -> throw new IllegalStateException("unknown trace event type " + type[slot]);
        }
    }

    private void instant(JsonGenerator g, String name, String cat, long atNs, int pid, int tid, String argName,
                         double argValue) throws IOException {
        g.writeStartObject();
        g.writeStringField("name", name);
        g.writeStringField("cat", cat);
        g.writeStringField("ph", "i");
        g.writeStringField("s", "t");
        g.writeNumberField("ts", us(atNs));
        g.writeNumberField("pid", pid);
        g.writeNumberField("tid", tid);
        if (argName != null) {
            g.writeObjectFieldStart("args");
            g.writeNumberField(argName, argValue);
            g.writeEndObject();
        }
        g.writeEndObject();
    }

    private double us(long ns) {
        return (ns - originNs) / 1e3;
    }
}
