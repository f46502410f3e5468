package io.rtaware.ros2msg;

import java.util.Objects;

/**
 * A ROS 2 message type as other ROS 2 software names it: its full name, its DDS type name, its
 * RIHS01 type hash (Jazzy definitions) and its definition. Immutable.
 */
public final class Ros2MessageType {

    private final MessageDefinition definition;
    private final String typeHash;

    /**
     * @param definition the definition
     * @param typeHash the RIHS01 hash, {@code RIHS01_} followed by 64 hex digits
     */
    public Ros2MessageType(MessageDefinition definition, String typeHash) {
        this.definition = Objects.requireNonNull(definition);
        if (!typeHash.matches("RIHS01_[0-9a-f]{64}")) {
            throw new IllegalArgumentException("not a RIHS01 type hash: " + typeHash);
        }
        this.typeHash = typeHash;
    }

    /** @return the full name, e.g. {@code sensor_msgs/msg/LaserScan} (MCAP schema name) */
    public String name() {
        return definition.name();
    }

    /** @return the DDS type name, e.g. {@code sensor_msgs::msg::dds_::LaserScan_} */
    public String ddsTypeName() {
        String n = definition.name();
        int last = n.lastIndexOf('/');
        return n.substring(0, last).replace("/", "::") + "::dds_::" + n.substring(last + 1) + "_";
    }

    /** @return the RIHS01 type hash of the Jazzy definition */
    public String typeHash() {
        return typeHash;
    }

    /** @return the definition */
    public MessageDefinition definition() {
        return definition;
    }

    /** @return the concatenated definition for an MCAP {@code ros2msg} schema */
    public String schemaText() {
        return definition.schemaText();
    }

    @Override
    public String toString() {
        return name();
    }
}
