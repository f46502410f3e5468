package io.rtaware.record;

import io.rtaware.record.ring.MultiProducerRing;
import io.rtaware.record.ring.SlotReader;
import io.rtaware.ros2msg.cdr.CdrWriter;
import java.io.IOException;
import java.util.List;
import java.util.Locale;

/**
 * Monitor events and log lines: filled by any thread (task threads, the watchdog, the command's
 * supervisor), written as {@code rtaware_msgs/msg/MonitorEvent} on {@code /rtaware/events} (monitor
 * events) and as {@code rcl_interfaces/msg/Log} on {@code /rosout} (both: a line in words per
 * monitor event, so ROS 2 and Foxglove log viewers show misses beside the run's other log lines).
 */
final class EventRing implements RecorderRing {

    /** One event; its references are cleared once it is read, so the ring keeps no object alive. */
    private static final class Event {
        byte kind;
        byte level;
        int task;
        long timeNs;
        long a;
        long b;
        boolean flag;
        String key;
        Object detail;

        void clear() {
            key = null;
            detail = null;
        }
    }

    private final int channel;
    private final int rosout;
    private final long logTimeOffsetNs;
    private final List<String> taskNames;
    private final MultiProducerRing<Event> ring;
    private final SlotReader<Event, MessageSink, WriterScratch> writer = this::write;
    /** The line of the event being written (writer thread only). */
    private final StringBuilder line = new StringBuilder(256);
    /** Log lines written, numbering their messages (writer thread only). */
    private long lines;

    /**
     * @param channel the {@code /rtaware/events} channel
     * @param rosout the {@code /rosout} channel
     * @param taskNames task names by index
     * @param slots ring slots
     * @param logTimeOffsetNs added to world time to make a log line's stamp (Unix-epoch ns)
     */
    EventRing(int channel, int rosout, List<String> taskNames, int slots, long logTimeOffsetNs) {
        this.channel = channel;
        this.rosout = rosout;
        this.taskNames = taskNames;
        this.logTimeOffsetNs = logTimeOffsetNs;
        ring = new MultiProducerRing<>(slots, i -> new Event());
    }

    /** Producer (any thread): copies an event into a free slot; false (dropped) if none is free. */
    boolean offer(byte k, int t, long timeNs, long x, long y, boolean f, String keyName, Object d) {
        return offer(k, (byte) 0, t, timeNs, x, y, f, keyName, d);
    }

    /**
     * Producer (any thread): a log line of the run's own ({@code /rosout} only); false (dropped)
     * if no slot is free.
     */
    boolean offerLine(byte level, long timeNs, String name, String text) {
        return offer(RunRecorder.LOG_LINE, level, -1, timeNs, 0, 0, false, name, text);
    }

    private boolean offer(byte k, byte level, int t, long timeNs, long x, long y, boolean f, String keyName, Object d) {
        long position = ring.claim();
        if (position < 0) {
            return false;
        }
        Event e = ring.slot(position);
        e.kind = k;
        e.level = level;
        e.task = t;
        e.timeNs = timeNs;
        e.a = x;
        e.b = y;
        e.flag = f;
        e.key = keyName;
        e.detail = d;
        ring.publish(position);
        return true;
    }

    @Override
    public int drain(MessageSink sink, WriterScratch scratch) throws IOException {
        return ring.drain(writer, sink, scratch);
    }

    private void write(Event e, long position, MessageSink sink, WriterScratch scratch) throws IOException {
        String name;
        byte level;
        line.setLength(0);
        if (e.kind == RunRecorder.LOG_LINE) {
            name = e.key;
            level = e.level;
            line.append(e.detail);
        } else {
            name = taskNames.get(e.task);
            TimingEncoder.event(scratch.cdr, e.kind, name, e.key, e.timeNs, e.a, e.b, e.flag, e.detail);
            sink.write(channel, position, e.timeNs, e.timeNs, scratch.cdr.buffer(), 0, scratch.cdr.size());
            level = describe(e);
        }
        log(scratch.cdr, logTimeOffsetNs + e.timeNs, level, name, line);
        sink.write(rosout, lines++, e.timeNs, e.timeNs, scratch.cdr.buffer(), 0, scratch.cdr.size());
        e.clear();
    }

    /** Puts a monitor event in words into {@link #line}; returns its severity. */
    private byte describe(Event e) {
        switch (e.kind) {
            case RunRecorder.DEADLINE_MISS -> {
                line.append("deadline miss: the release at ").append(seconds(e.a)).append(" s did not end by its deadline at ")
                        .append(seconds(e.b)).append(" s").append(e.flag ? " (still running)" : "");
                return RunRecorder.WARN;
            }
            case RunRecorder.EXPIRED_READ -> {
                line.append("expired read: '").append(e.key).append("' was ").append(millis(e.a))
                        .append(" ms old, older than its maximum age of ").append(millis(e.b)).append(" ms");
                return RunRecorder.WARN;
            }
            case RunRecorder.PERIOD_CHANGE -> {
                line.append("period changed from ").append(millis(e.a)).append(" ms to ").append(millis(e.b)).append(" ms: ")
                        .append(e.detail);
                return RunRecorder.INFO;
            }
            default -> {
                line.append("task error: ").append(e.detail);
                return RunRecorder.ERROR_LEVEL;
            }
        }
    }

    private static String seconds(long worldNs) {
        return String.format(Locale.ROOT, "%.3f", worldNs / 1e9);
    }

    private static String millis(long ns) {
        return String.format(Locale.ROOT, "%.1f", ns / 1e6);
    }

    /** Encodes an {@code rcl_interfaces/msg/Log}: no file, function or line (rtaware is not C). */
    static void log(CdrWriter cdr, long stampNs, byte level, String name, CharSequence text) {
        cdr.begin();
        cdr.writeInt32((int) Math.floorDiv(stampNs, 1_000_000_000L));
        cdr.writeInt32((int) Math.floorMod(stampNs, 1_000_000_000L));
        cdr.writeInt8(level);
        cdr.writeString(name);
        cdr.writeString(text);
        cdr.writeString("");
        cdr.writeString("");
        cdr.writeInt32(0);
    }

    @Override
    public void discard() {
        ring.discard(Event::clear);
    }
}
