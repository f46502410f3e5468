package io.rtaware.record;

import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.monitor.TaskInfo;
import io.rtaware.ros2msg.DiagnosticArrayCodec;
import io.rtaware.ros2msg.TaskDiagnostics;
import io.rtaware.ros2msg.value.DiagnosticArray;
import java.io.IOException;
import java.util.List;

/**
 * {@code /diagnostics} of a recording: once every {@value #PERIOD_NS} ns of world time, a
 * {@code diagnostic_msgs/msg/DiagnosticArray} with one status per task from the monitor's counters
 * ({@link TaskDiagnostics}, the statuses the ROS 2 exporter publishes), so that a viewer's table
 * shows every task's latest figures in one message. Not a ring: the writer thread samples the
 * counters when its pass finds the time has come (the task threads do nothing for it), so the
 * arrays are at most one writer pass later than each second.
 */
final class HealthRing implements RecorderRing {

    /** World time between arrays. */
    static final long PERIOD_NS = 1_000_000_000L;

    private final Monitor monitor;
    private final List<TaskInfo> tasks;
    private final int channel;
    private final long logTimeOffsetNs;
    private final DiagnosticArray array;
    private final TaskDiagnostics statuses;
    private final DiagnosticArrayCodec codec = new DiagnosticArrayCodec();
    private long nextNs;
    private long written;

    /**
     * @param monitor the monitor whose counters are sampled
     * @param channel the {@code /diagnostics} channel
     * @param startNs world time of the recording's start (the first array is a period later)
     * @param logTimeOffsetNs added to world time to make the header's stamp
     */
    HealthRing(Monitor monitor, int channel, long startNs, long logTimeOffsetNs) {
        this.monitor = monitor;
        this.tasks = monitor.tasks();
        this.channel = channel;
        this.logTimeOffsetNs = logTimeOffsetNs;
        this.nextNs = startNs + PERIOD_NS;
        this.array = new DiagnosticArray(tasks.size(), TaskDiagnostics.VALUES);
        this.statuses = TaskDiagnostics.of(tasks);
    }

    @Override
    public int drain(MessageSink sink, WriterScratch scratch) throws IOException {
        long nowNs = monitor.clock().nanos();
        if (nowNs < nextNs) {
            return 0;
        }
        array.clear();
        for (TaskInfo task : tasks) {
            statuses.fill(task, monitor.counters(task.index()), array.add());
        }
        scratch.header.set(logTimeOffsetNs + nowNs, "");
        codec.encode(scratch.header, array, scratch.cdr);
        sink.write(channel, written++, nowNs, nowNs, scratch.cdr.buffer(), 0, scratch.cdr.size());
        nextNs += ((nowNs - nextNs) / PERIOD_NS + 1) * PERIOD_NS; // the first second after now
        return 1;
    }

    @Override
    public void discard() {
        // nothing is held: the next pass samples the counters again
    }
}
