package io.rtaware.record;

import io.rtaware.core.data.Key;
import io.rtaware.core.data.StateValue;
import io.rtaware.record.encode.StateFields;
import io.rtaware.record.ring.SingleProducerRing;
import io.rtaware.record.ring.SlotReader;
import io.rtaware.ros2msg.statistics.TimingStatistics;
import java.io.IOException;

/**
 * One key's committed values: filled by the key's producer (one thread at a time: a key has one
 * producing task), each value copied into a buffer of the ring's own; written by the key's
 * {@link KeyChannels}.
 */
final class CommitRing implements RecorderRing {

    /** One commit: a buffer of the key's type and when it was committed. */
    private static final class Commit {
        final StateValue<?> value;
        long timeNs;
        long generation;

        Commit(StateValue<?> value) {
            this.value = value;
        }
    }

    private final SingleProducerRing<Commit> ring;
    private final KeyChannels channels;
    private final int keyIndex;
    /** The run's statistics, or null. */
    private final TimingStatistics statistics;
    private final SlotReader<Commit, MessageSink, WriterScratch> writer = this::write;

    CommitRing(Key<?> key, int keyIndex, KeyChannels channels, TimingStatistics statistics, int mostSlots,
               long mostBytes) {
        this.channels = channels;
        this.keyIndex = keyIndex;
        this.statistics = statistics;
        StateValue<?> first = key.newBuffer();
        long valueBytes = StateFields.of(key.type()).estimateBytes(first);
        int n = (int) Math.max(Math.min(8, mostSlots), Math.min(mostSlots, mostBytes / Math.max(1, valueBytes)));
        ring = new SingleProducerRing<>(n, i -> new Commit(i == 0 ? first : key.newBuffer()));
    }

    /** Producer: copies a value into a free slot; false (dropped) if none is free. */
    @SuppressWarnings({"unchecked", "rawtypes"})
    boolean offer(StateValue<?> value, long generation, long timeNs) {
        long position = ring.claim();
        if (position < 0) {
            return false;
        }
        Commit c = ring.slot(position);
        ((StateValue) c.value).copyFrom(value);
        c.timeNs = timeNs;
        c.generation = generation;
        ring.publish(position);
        return true;
    }

    @Override
    public int drain(MessageSink sink, WriterScratch scratch) throws IOException {
        return ring.drain(writer, sink, scratch);
    }

    private void write(Commit c, long position, MessageSink sink, WriterScratch scratch) throws IOException {
        channels.write(c.value, c.generation, c.timeNs, sink, scratch);
        if (statistics != null) {
            statistics.commit(keyIndex, c.generation, c.timeNs);
        }
    }

    @Override
    public void discard() {
        ring.discard(c -> { });
    }
}
