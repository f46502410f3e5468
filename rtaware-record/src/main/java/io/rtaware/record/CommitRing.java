package io.rtaware.record;

import io.rtaware.core.data.Key;
import io.rtaware.core.data.StateValue;
import io.rtaware.record.encode.StateFields;
import io.rtaware.record.ring.SingleProducerSequence;
import java.io.IOException;

/**
 * One key's committed values: filled by the key's producer (one thread at a time: a key has one
 * producing task), each value copied into a buffer of the ring's own; written by the key's
 * {@link KeyChannels}.
 */
final class CommitRing implements RecorderRing {

    private final StateValue<?>[] slots;
    private final long[] times;
    private final long[] generations;
    private final SingleProducerSequence sequence;
    private final KeyChannels channels;

    CommitRing(Key<?> key, KeyChannels channels, int mostSlots, long mostBytes) {
        this.channels = channels;
        StateValue<?> first = key.newBuffer();
        long valueBytes = StateFields.of(key.type()).estimateBytes(first);
        int n = (int) Math.max(Math.min(8, mostSlots), Math.min(mostSlots, mostBytes / Math.max(1, valueBytes)));
        slots = new StateValue<?>[n];
        slots[0] = first;
        for (int i = 1; i < n; i++) {
            slots[i] = key.newBuffer();
        }
        times = new long[n];
        generations = new long[n];
        sequence = new SingleProducerSequence(n);
    }

    /** Producer: copies a value into a free slot; false (dropped) if none is free. */
    @SuppressWarnings({"unchecked", "rawtypes"})
    boolean offer(StateValue<?> value, long generation, long timeNs) {
        long h = sequence.claim();
        if (h < 0) {
            return false;
        }
        int s = sequence.slot(h);
        ((StateValue) slots[s]).copyFrom(value);
        times[s] = timeNs;
        generations[s] = generation;
        sequence.publish(h);
        return true;
    }

    @Override
    public int drain(MessageSink sink, WriterScratch scratch) throws IOException {
        long t = sequence.consumed();
        long h = sequence.published();
        for (long i = t; i < h; i++) {
            int s = sequence.slot(i);
            channels.write(slots[s], generations[s], times[s], sink, scratch);
            sequence.consumedUpTo(i + 1);
        }
        return (int) (h - t);
    }

    @Override
    public void discard() {
        sequence.discardAll();
    }
}
