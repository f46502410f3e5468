package io.rtaware.record;

import io.rtaware.record.ring.MultiProducerRing;
import io.rtaware.record.ring.SlotReader;
import java.io.IOException;
import java.util.List;

/**
 * Monitor events: filled by any thread (task threads, the watchdog), written as
 * {@code rtaware_msgs/msg/MonitorEvent} on {@code /rtaware/events}.
 */
final class EventRing implements RecorderRing {

    /** One event; its references are cleared once it is read, so the ring keeps no object alive. */
    private static final class Event {
        byte kind;
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
    private final List<String> taskNames;
    private final MultiProducerRing<Event> ring;
    private final SlotReader<Event, MessageSink, WriterScratch> writer = this::write;

    EventRing(int channel, List<String> taskNames, int slots) {
        this.channel = channel;
        this.taskNames = taskNames;
        ring = new MultiProducerRing<>(slots, i -> new Event());
    }

    /** Producer (any thread): copies an event into a free slot; false (dropped) if none is free. */
    boolean offer(byte k, int t, long timeNs, long x, long y, boolean f, String keyName, Object d) {
        long position = ring.claim();
        if (position < 0) {
            return false;
        }
        Event e = ring.slot(position);
        e.kind = k;
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
        TimingEncoder.event(scratch.cdr, e.kind, taskNames.get(e.task), e.key, e.timeNs, e.a, e.b, e.flag, e.detail);
        sink.write(channel, position, e.timeNs, e.timeNs, scratch.cdr.buffer(), 0, scratch.cdr.size());
        e.clear();
    }

    @Override
    public void discard() {
        ring.discard(Event::clear);
    }
}
