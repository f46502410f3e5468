package io.rtaware.record;

import io.rtaware.ros2msg.MetricsMessageCodec;
import io.rtaware.ros2msg.Ros2Header;
import io.rtaware.ros2msg.cdr.CdrWriter;
import io.rtaware.ros2msg.statistics.TimingStatistics;
import io.rtaware.ros2msg.value.MetricsMessage;
import java.io.IOException;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The recording's {@code /statistics}: the {@link TimingStatistics} of the run, fed by the commit
 * and cycle rings as the writer thread drains them, and this ring last in the writer's pass, where
 * it publishes the windows that pass completed. Each message is written with its window's end as
 * log and publish time. Writer thread only (then {@link #finish} on the finishing thread, after
 * the writer thread has stopped).
 */
final class StatisticsChannel implements RecorderRing {

    private final int channel;
    private final MessageSink sink;
    private final TimingStatistics statistics;
    private final MetricsMessageCodec codec = new MetricsMessageCodec();
    private final Ros2Header header = new Ros2Header();
    private final CdrWriter cdr;
    private long sequence;

    /**
     * @param channel the {@code /statistics} channel
     * @param sink where the messages go
     * @param taskNames task names by task index
     * @param taskInputs each task's input key names
     * @param keyNames key names by key index, null for a key not recorded
     * @param plan the recording's start (the first window's), log-time offset (the stamps') and
     *     reorder window (the statistics' grace: how long a quiet task holds a second back)
     */
    StatisticsChannel(int channel, MessageSink sink, List<String> taskNames, List<List<String>> taskInputs,
                      List<String> keyNames, RecordingPlan plan) {
        this.channel = channel;
        this.sink = sink;
        int longestName = 0;
        for (String name : taskNames) {
            longestName = Math.max(longestName, name.length());
        }
        for (String name : keyNames) {
            longestName = Math.max(longestName, name == null ? 0 : name.length());
        }
        cdr = new CdrWriter(1024 + 3 * longestName); // three bytes of UTF-8 at most per char of a name
        statistics = new TimingStatistics(taskNames, taskInputs, keyNames, plan.worldStartNs(), plan.logTimeOffsetNs(),
                plan.reorderWindowNs(), this::write);
    }

    /**
     * @return the log time (world time) of the next messages to come: the end of the window not
     *     yet published, before which the file must not move on
     */
    long nextLogTimeNs() {
        return statistics.nextWindowStartNs() + TimingStatistics.WINDOW_NS;
    }

    /** @return the statistics the commit and cycle rings feed */
    TimingStatistics statistics() {
        return statistics;
    }

    private void write(MetricsMessage message, long windowStopWorldNs) throws IOException {
        codec.encode(header, message, cdr);
        sink.write(channel, sequence++, windowStopWorldNs, windowStopWorldNs, cdr.buffer(), 0, cdr.size());
    }

    @Override
    public int drain(MessageSink unused, WriterScratch scratch) throws IOException {
        return statistics.drained(Long.MIN_VALUE);
    }

    @Override
    public void discard() {
        // nothing held: the statistics are no longer fed once the writing has failed
    }

    /**
     * Publishes every window that ended by the last record written (not the one still running).
     *
     * @throws IOException if writing fails
     */
    void finish() throws IOException {
        statistics.finish(Long.MIN_VALUE);
    }

    /** @return the {@code rtaware.statistics} metadata: what the statistics of the file could not count */
    Map<String, String> metadata() {
        Map<String, String> m = new LinkedHashMap<>();
        m.put("window_ns", Long.toString(TimingStatistics.WINDOW_NS));
        m.put("windows", Long.toString(statistics.windowsPublished()));
        m.put("late_records", Long.toString(statistics.lateRecords()));
        m.put("unmatched_ages", Long.toString(statistics.unmatchedAges()));
        return m;
    }
}
