package io.rtaware.record;

import io.rtaware.record.ring.MultiProducerSequence;
import java.io.IOException;
import java.util.List;

/**
 * Monitor events: filled by any thread (task threads, the watchdog), written as
 * {@code rtaware_msgs/msg/MonitorEvent} on {@code /rtaware/events}.
 */
final class EventRing implements RecorderRing {

    private final int channel;
    private final List<String> taskNames;
    private final MultiProducerSequence sequence;
    private final byte[] kind;
    private final int[] task;
    private final long[] time;
    private final long[] a;
    private final long[] b;
    private final boolean[] flag;
    private final String[] key;
    private final Object[] detail;

    EventRing(int channel, List<String> taskNames, int slots) {
        this.channel = channel;
        this.taskNames = taskNames;
        sequence = new MultiProducerSequence(slots);
        kind = new byte[slots];
        task = new int[slots];
        time = new long[slots];
        a = new long[slots];
        b = new long[slots];
        flag = new boolean[slots];
        key = new String[slots];
        detail = new Object[slots];
    }

    /** Producer (any thread): copies an event into a free slot; false (dropped) if none is free. */
    boolean offer(byte k, int t, long timeNs, long x, long y, boolean f, String keyName, Object d) {
        long c = sequence.claim();
        if (c < 0) {
            return false;
        }
        int s = sequence.slot(c);
        kind[s] = k;
        task[s] = t;
        time[s] = timeNs;
        a[s] = x;
        b[s] = y;
        flag[s] = f;
        key[s] = keyName;
        detail[s] = d;
        sequence.publish(c);
        return true;
    }

    @Override
    public int drain(MessageSink sink, WriterScratch scratch) throws IOException {
        int count = 0;
        for (long p = sequence.nextPublished(); p >= 0; p = sequence.nextPublished()) {
            int s = sequence.slot(p);
            TimingEncoder.event(scratch.cdr, kind[s], taskNames.get(task[s]), key[s], time[s], a[s], b[s], flag[s],
                    detail[s]);
            sink.write(channel, p, time[s], time[s], scratch.cdr.buffer(), 0, scratch.cdr.size());
            detail[s] = null;
            key[s] = null;
            sequence.consumedOne();
            count++;
        }
        return count;
    }

    @Override
    public void discard() {
        for (long p = sequence.nextPublished(); p >= 0; p = sequence.nextPublished()) {
            int s = sequence.slot(p);
            detail[s] = null;
            key[s] = null;
            sequence.consumedOne();
        }
    }
}
