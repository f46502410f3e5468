package io.rtaware.record;

import io.rtaware.record.ring.SingleProducerSequence;
import java.io.IOException;

/**
 * One task's cycle records: filled by the task's thread (one at a time), written as
 * {@code rtaware_msgs/msg/TaskCycle} on the task's timing channel.
 */
final class CycleRing implements RecorderRing {

    private final int channel;
    private final int inputs;
    private final byte[] outcome;
    private final long[] release;
    private final long[] start;
    private final long[] end;
    private final long[] skipped;
    private final long[] generations;
    private final long[] numbers;
    private final SingleProducerSequence sequence;
    /** Records offered so far, dropped ones included (producer thread only). */
    private long offered;

    CycleRing(int channel, int inputs, int slots) {
        this.channel = channel;
        this.inputs = inputs;
        outcome = new byte[slots];
        release = new long[slots];
        start = new long[slots];
        end = new long[slots];
        skipped = new long[slots];
        numbers = new long[slots];
        generations = new long[slots * Math.max(1, inputs)];
        sequence = new SingleProducerSequence(slots);
    }

    /** Producer: copies a record into a free slot; false (dropped, still numbered) if none is free. */
    boolean offer(byte what, long releaseNs, long startNs, long endNs, long skips, long[] inputGenerations) {
        long number = offered++;
        long h = sequence.claim();
        if (h < 0) {
            return false;
        }
        int s = sequence.slot(h);
        numbers[s] = number;
        outcome[s] = what;
        release[s] = releaseNs;
        start[s] = startNs;
        end[s] = endNs;
        skipped[s] = skips;
        for (int i = 0; i < inputs; i++) {
            generations[s * inputs + i] = inputGenerations == null ? 0 : inputGenerations[i];
        }
        sequence.publish(h);
        return true;
    }

    @Override
    public int drain(MessageSink sink, WriterScratch scratch) throws IOException {
        long t = sequence.consumed();
        long h = sequence.published();
        for (long i = t; i < h; i++) {
            int s = sequence.slot(i);
            TimingEncoder.cycle(scratch.cdr, outcome[s], release[s], start[s], end[s], skipped[s], generations,
                    s * inputs, inputs);
            sink.write(channel, numbers[s], end[s], end[s], scratch.cdr.buffer(), 0, scratch.cdr.size());
            sequence.consumedUpTo(i + 1);
        }
        return (int) (h - t);
    }

    @Override
    public void discard() {
        sequence.discardAll();
    }
}
