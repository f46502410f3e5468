package io.rtaware.ros2msg.statistics;

import io.rtaware.ros2msg.value.MetricsMessage;
import java.io.IOException;

/** Where {@link TimingStatistics} hands each message it completes: a publisher, a recording. */
@FunctionalInterface
public interface MetricsSink {

    /**
     * Takes one message. Called on the statistics' owner's thread.
     *
     * @param message the message, valid during the call only (it is reused)
     * @param windowStopWorldNs the world time at which its window ended (the message's stamps are
     *     that plus the statistics' stamp offset)
     * @throws IOException if it cannot be published or written
     */
    void publish(MetricsMessage message, long windowStopWorldNs) throws IOException;
}
