package io.rtaware.record;

import io.rtaware.core.monitor.CycleOutcome;
import io.rtaware.record.ring.SingleProducerRing;
import io.rtaware.record.ring.SlotReader;
import io.rtaware.ros2msg.statistics.TimingStatistics;
import java.io.IOException;

/**
 * One task's cycle records: filled by the task's thread (one at a time), written as
 * {@code rtaware_msgs/msg/TaskCycle} on the task's timing channel, and handed to the run's
 * statistics, if any, as they are written.
 */
final class CycleRing implements RecorderRing {

    /** One cycle record. */
    private static final class Cycle {
        final long[] generations;
        long number;
        byte outcome;
        long releaseNs;
        long startNs;
        long endNs;
        long skipped;

        Cycle(int inputs) {
            generations = new long[inputs];
        }
    }

    private final int channel;
    private final int task;
    /** The run's statistics, or null. */
    private final TimingStatistics statistics;
    private final int inputs;
    private final SingleProducerRing<Cycle> ring;
    private final SlotReader<Cycle, MessageSink, WriterScratch> writer = this::write;
    /** Records offered so far, dropped ones included (producer thread only). */
    private long offered;

    CycleRing(int channel, int task, TimingStatistics statistics, int inputs, int slots) {
        this.channel = channel;
        this.task = task;
        this.statistics = statistics;
        this.inputs = inputs;
        ring = new SingleProducerRing<>(slots, i -> new Cycle(inputs));
    }

    /** Producer: copies a record into a free slot; false (dropped, still numbered) if none is free. */
    boolean offer(byte what, long releaseNs, long startNs, long endNs, long skips, long[] inputGenerations) {
        long number = offered++;
        long position = ring.claim();
        if (position < 0) {
            return false;
        }
        Cycle c = ring.slot(position);
        c.number = number;
        c.outcome = what;
        c.releaseNs = releaseNs;
        c.startNs = startNs;
        c.endNs = endNs;
        c.skipped = skips;
        for (int i = 0; i < inputs; i++) {
            c.generations[i] = inputGenerations == null ? 0 : inputGenerations[i];
        }
        ring.publish(position);
        return true;
    }

    @Override
    public int drain(MessageSink sink, WriterScratch scratch) throws IOException {
        return ring.drain(writer, sink, scratch);
    }

    private void write(Cycle c, long position, MessageSink sink, WriterScratch scratch) throws IOException {
        TimingEncoder.cycle(scratch.cdr, c.outcome, c.releaseNs, c.startNs, c.endNs, c.skipped, c.generations, 0,
                inputs);
        sink.write(channel, c.number, c.endNs, c.endNs, scratch.cdr.buffer(), 0, scratch.cdr.size());
        if (statistics == null) {
            return;
        }
        if (c.outcome == RunRecorder.SKIPPED) {
            statistics.skipped(task, c.skipped, c.endNs);
        } else {
            statistics.cycle(task, outcomeOf(c.outcome), c.releaseNs, c.startNs, c.endNs, c.generations);
        }
    }

    /** The monitor's outcome of a cycle record's code (not {@link RunRecorder#SKIPPED}). */
    private static CycleOutcome outcomeOf(byte code) {
        return switch (code) {
            case RunRecorder.MISS -> CycleOutcome.MISS;
            case RunRecorder.STALE -> CycleOutcome.STALE;
            case RunRecorder.ERROR -> CycleOutcome.ERROR;
            default -> CycleOutcome.OK;
        };
    }

    @Override
    public void discard() {
        ring.discard(c -> { });
    }
}
