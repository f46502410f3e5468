package io.rtaware.record;

import io.rtaware.record.mcap.McapWriter;
import io.rtaware.ros2msg.cdr.CdrWriter;
import java.io.IOException;

/**
 * The {@code /clock} channel of a recording on simulated time: a {@code rosgraph_msgs/msg/Clock}
 * every {@code periodNs} of world time from the recording's start, each carrying its own log
 * time, written by the log-time ordered sink just before the first message at or after it
 * ({@link #upTo}), so ticks stay in order with everything else and end with the last message.
 * Writer thread only; allocates nothing.
 */
final class ClockTicks {

    private static final long NS_PER_S = 1_000_000_000L;

    private final McapWriter writer;
    private final int channel;
    private final long periodNs;
    private final long logTimeOffsetNs;
    private final CdrWriter cdr = new CdrWriter(64);
    private long nextNs;
    private long written;

    /**
     * @param writer the file
     * @param channel the {@code /clock} channel
     * @param startNs world time of the first tick
     * @param periodNs world time between ticks, positive
     * @param logTimeOffsetNs added to world time to make log time (and the tick's time)
     */
    ClockTicks(McapWriter writer, int channel, long startNs, long periodNs, long logTimeOffsetNs) {
        this.writer = writer;
        this.channel = channel;
        this.nextNs = startNs;
        this.periodNs = periodNs;
        this.logTimeOffsetNs = logTimeOffsetNs;
    }

    /**
     * Writes every tick at or before {@code worldNs} not written yet.
     *
     * @param worldNs world time of the message about to be written
     * @throws IOException if writing fails
     */
    void upTo(long worldNs) throws IOException {
        while (nextNs <= worldNs) {
            long logNs = nextNs + logTimeOffsetNs;
            cdr.begin();
            cdr.writeInt32((int) Math.floorDiv(logNs, NS_PER_S));
            cdr.writeInt32((int) Math.floorMod(logNs, NS_PER_S));
            writer.writeMessage(channel, written++, logNs, logNs, cdr.buffer(), 0, cdr.size());
            nextNs += periodNs;
        }
    }
}
