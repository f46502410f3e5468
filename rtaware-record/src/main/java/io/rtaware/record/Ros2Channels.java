package io.rtaware.record;

import io.rtaware.record.mcap.McapWriter;
import java.io.IOException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * The channel layout of a recording in the MCAP {@code ros2} profile, as {@code ros2 bag record}
 * writes it: every channel {@code cdr} with a {@code ros2msg} schema (each schema written once),
 * with the channel metadata rosbag2 writes and reads ({@code offered_qos_profiles}, and
 * {@code topic_type_hash} where the type's RIHS01 hash is known), and at the end the
 * {@code rosbag2} metadata record ({@link #writeBagMetadata}). QoS and bag metadata are in the
 * form of rosbag2's metadata version {@value #BAG_VERSION} (Jazzy: QoS policies as numbers).
 * Every channel is declared to the plan's {@link RecordingTap} too, if it has one; without a
 * file (a recording for its tap alone) the channels are numbered here as the file would number
 * them, from 1.
 */
final class Ros2Channels {

    /** The rosbag2 metadata version written. */
    static final int BAG_VERSION = 8;
    /** The distribution named in the bag metadata. */
    static final String ROS_DISTRO = "jazzy";
    /** rmw's infinite duration, as rosbag2 writes it. */
    private static final String INFINITE = "\n    sec: 9223372036\n    nsec: 854775807";

    /** What a topic's publisher offers. */
    enum Qos {
        /** Reliable, volatile, keep last 10: the rclcpp default. */
        RELIABLE_VOLATILE(10, 1, 2),
        /** Reliable, transient local, keep last 1: a latched topic ({@code /map}, {@code /tf_static}). */
        RELIABLE_TRANSIENT_LOCAL(1, 1, 1),
        /** Reliable, volatile, keep last 100: {@code /tf}, as tf2's broadcaster offers it. */
        TF(100, 1, 2),
        /** Best effort, volatile, keep last 1: {@code /clock}, as rclcpp's {@code ClockQoS} offers it. */
        CLOCK(1, 2, 2),
        /** Reliable, transient local, keep last 1000: {@code /rosout}, as rcl's rosout publisher offers it. */
        ROSOUT(1000, 1, 1);

        private final int depth;
        private final int reliability;
        private final int durability;

        Qos(int depth, int reliability, int durability) {
            this.depth = depth;
            this.reliability = reliability;
            this.durability = durability;
        }

        /** @return the YAML rosbag2 stores in {@code offered_qos_profiles} (one profile) */
        String yaml() {
            return "- history: 1\n  depth: " + depth + "\n  reliability: " + reliability + "\n  durability: "
                    + durability
                    + "\n  deadline:" + INFINITE + "\n  lifespan:" + INFINITE + "\n  liveliness: 1"
                    + "\n  liveliness_lease_duration:" + INFINITE + "\n  avoid_ros_namespace_conventions: false\n";
        }
    }

    private record Channel(int id, String topic, String type, String qos, String typeHash) {
    }

    private final McapWriter writer;
    private final RecordingTap tap;
    private final Map<String, Integer> schemas = new HashMap<>();
    private final List<Channel> channels = new ArrayList<>();

    /**
     * @param writer the file, or null when recording for the tap alone
     * @param tap what else is told of every channel, or null
     */
    Ros2Channels(McapWriter writer, RecordingTap tap) {
        this.writer = writer;
        this.tap = tap;
    }

    /**
     * Adds a channel (to the file, if there is one, and to the tap), or returns the one of the
     * same topic and type added before.
     *
     * @param topic the topic
     * @param type the message type, e.g. {@code sensor_msgs/msg/LaserScan}
     * @param schemaText its {@code ros2msg} definition with its dependencies
     * @param typeHash its RIHS01 hash, or null if unknown
     * @param qos what its publisher offers
     * @param metadata rtaware's own channel metadata
     * @return the channel id
     * @throws IOException if writing fails
     */
    int add(String topic, String type, String schemaText, String typeHash, Qos qos, Map<String, String> metadata)
            throws IOException {
        for (Channel c : channels) {
            if (c.topic().equals(topic) && c.type().equals(type)) {
                return c.id(); // one channel per topic (e.g. /tf from odometry and from the ground truth)
            }
        }
        int id;
        if (writer != null) {
            Integer schema = schemas.get(type);
            if (schema == null) {
                schema = writer.addSchema(type, TapChannel.SCHEMA_ENCODING, schemaText);
                schemas.put(type, schema);
            }
            Map<String, String> all = new LinkedHashMap<>(metadata);
            all.put("offered_qos_profiles", qos.yaml());
            if (typeHash != null) {
                all.put("topic_type_hash", typeHash);
            }
            id = writer.addChannel(schema, topic, TapChannel.MESSAGE_ENCODING, all);
        } else {
            id = channels.size() + 1;
        }
        channels.add(new Channel(id, topic, type, qos.yaml(), typeHash));
        if (tap != null) {
            tap.channel(new TapChannel(id, topic, type, schemaText, qos == Qos.RELIABLE_TRANSIENT_LOCAL));
        }
        return id;
    }

    /**
     * Writes the {@code rosbag2} metadata record as the rosbag2 MCAP storage plugin does: the
     * bag's metadata as YAML under {@code serialized_metadata}, and {@code ROS_DISTRO}.
     *
     * @param fileName the file's name (the bag's one relative file path)
     * @throws IOException if writing fails
     */
    void writeBagMetadata(String fileName) throws IOException {
        if (writer == null) {
            return;
        }
        long messages = writer.messageCount();
        long startNs = messages == 0 ? 0 : writer.messageStartNs();
        long durationNs = messages == 0 ? 0 : writer.messageEndNs() - startNs;
        StringBuilder y = new StringBuilder(4096);
        y.append("rosbag2_bagfile_information:\n");
        y.append("  version: ").append(BAG_VERSION).append('\n');
        y.append("  storage_identifier: mcap\n");
        y.append("  duration:\n    nanoseconds: ").append(durationNs).append('\n');
        y.append("  starting_time:\n    nanoseconds_since_epoch: ").append(startNs).append('\n');
        y.append("  message_count: ").append(messages).append('\n');
        y.append("  topics_with_message_count:\n");
        for (Channel c : channels) {
            y.append("    - topic_metadata:\n");
            y.append("        name: ").append(quoted(c.topic())).append('\n');
            y.append("        type: ").append(quoted(c.type())).append('\n');
            y.append("        serialization_format: cdr\n");
            y.append("        offered_qos_profiles: ").append(quoted(c.qos())).append('\n');
            y.append("        type_description_hash: ").append(quoted(c.typeHash() == null ? "" : c.typeHash()))
                    .append('\n');
            y.append("      message_count: ").append(writer.channelMessageCount(c.id())).append('\n');
        }
        y.append("  compression_format: \"\"\n");
        y.append("  compression_mode: \"\"\n");
        y.append("  relative_file_paths:\n    - ").append(quoted(fileName)).append('\n');
        y.append("  files:\n    - path: ").append(quoted(fileName)).append('\n');
        y.append("      starting_time:\n        nanoseconds_since_epoch: ").append(startNs).append('\n');
        y.append("      duration:\n        nanoseconds: ").append(durationNs).append('\n');
        y.append("      message_count: ").append(messages).append('\n');
        y.append("  custom_data: ~\n");
        y.append("  ros_distro: ").append(ROS_DISTRO).append('\n');
        Map<String, String> record = new LinkedHashMap<>();
        record.put("serialized_metadata", y.toString());
        record.put("ROS_DISTRO", ROS_DISTRO);
        writer.addMetadata("rosbag2", record);
    }

    /** A YAML double-quoted scalar. */
    static String quoted(String s) {
        StringBuilder out = new StringBuilder(s.length() + 2).append('"');
        for (int i = 0; i < s.length(); i++) {
            char ch = s.charAt(i);
            switch (ch) {
                case '"' -> out.append("\\\"");
                case '\\' -> out.append("\\\\");
                case '\n' -> out.append("\\n");
                case '\t' -> out.append("\\t");
                default -> {
                    if (ch < 0x20) {
                        out.append(String.format(Locale.ROOT, "\\x%02x", (int) ch));
                    } else {
                        out.append(ch);
                    }
                }
            }
        }
        return out.append('"').toString();
    }
}
