package io.rtaware.ros2.task;

import io.rtaware.zenoh.ZenohException;
import java.util.Objects;
import java.util.Set;
import java.util.function.Consumer;

/**
 * Tells once that an input topic is published with another type than the one the data task reads.
 * DDS matches a reader only to writers of its own type, and rmw_zenoh's keys carry the type, so
 * such a topic gives no sample and no error: without this a run sees silence. While the topic has
 * given no usable sample, the watch asks the ROS graph which types its publishers have, every
 * {@code intervalNs} of world time from {@code intervalNs} after its first check (at once after a
 * first sample that does not decode, which may be another type's); the first answer
 * that shows publishers, none of them of the expected type, becomes one line. The watch ends then,
 * at the topic's first usable sample, and at an answer that shows a publisher of the expected type
 * (the silence has another cause); while nobody publishes the topic, it goes on. Task-thread only.
 */
final class PublishedTypeWatch {

    /** Who publishes a topic with which types: {@code Ros2Context::publishedTypes}. */
    @FunctionalInterface
    interface Graph {

        /**
         * @param fullTopic a fully qualified topic name
         * @return the ROS 2 type names its publishers have
         * @throws ZenohException if the graph cannot be asked
         */
        Set<String> publishedTypes(String fullTopic) throws ZenohException;
    }

    private final String fullTopic;
    private final String wireName;
    private final String expectedType;
    private final long intervalNs;
    private final Graph graph;
    private final Consumer<String> notice;
    private long nextCheckNs = Long.MIN_VALUE;
    private boolean asked;
    private boolean askNow;
    private boolean ended;

    /**
     * @param fullTopic the topic, fully qualified ({@code /scan})
     * @param wireName its name on the wire ({@code rt/scan} on DDS), for the line
     * @param expectedType the ROS 2 type the task reads ({@code sensor_msgs/msg/LaserScan})
     * @param intervalNs world time between two questions to the graph, positive
     * @param graph the graph
     * @param notice where the one line goes
     */
    PublishedTypeWatch(String fullTopic, String wireName, String expectedType, long intervalNs, Graph graph,
                       Consumer<String> notice) {
        if (intervalNs <= 0) {
            throw new IllegalArgumentException("intervalNs must be positive: " + intervalNs);
        }
        this.fullTopic = Objects.requireNonNull(fullTopic, "fullTopic");
        this.wireName = Objects.requireNonNull(wireName, "wireName");
        this.expectedType = Objects.requireNonNull(expectedType, "expectedType");
        this.intervalNs = intervalNs;
        this.graph = Objects.requireNonNull(graph, "graph");
        this.notice = Objects.requireNonNull(notice, "notice");
    }

    /** The topic gave a usable sample: its type is right, the watch ends. */
    void usable() {
        ended = true;
    }

    /**
     * A sample of the topic did not decode: a writer of another type may have been routed to the
     * task (the DDS bridge routes a topic with the type it saw first), so unless the graph was
     * asked already, it is asked at the next check without waiting for the interval.
     */
    void undecodable() {
        askNow = !asked;
    }

    /**
     * @return true once the watch has ended (a usable sample, a line told, a publisher of the
     *     expected type seen, or the graph unreachable)
     */
    boolean ended() {
        return ended;
    }

    /**
     * Asks the graph when a question is due.
     *
     * @param nowNs world time now
     */
    void check(long nowNs) {
        if (ended) {
            return;
        }
        if (!askNow) {
            if (nextCheckNs == Long.MIN_VALUE) {
                nextCheckNs = nowNs + intervalNs;
                return;
            }
            if (nowNs < nextCheckNs) {
                return;
            }
        }
        askNow = false;
        asked = true;
        nextCheckNs = nowNs + intervalNs;
        Set<String> types;
        try {
            types = graph.publishedTypes(fullTopic);
        } catch (ZenohException e) {
            ended = true;
            notice.accept("the ROS graph could not be asked which types " + wireName + " is published as: "
                    + e.getMessage());
            return;
        }
        if (types.contains(expectedType)) {
            ended = true; // a publisher of the right type: the silence has another cause
        } else if (!types.isEmpty()) {
            ended = true;
            notice.accept(wireName + " is published as " + String.join(" and ", types) + ", rtaware expects "
                    + expectedType + ": none of its samples can be read");
        }
    }
}
