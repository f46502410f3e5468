package io.rtaware.ros2.graph;

/**
 * The QoS policies rtaware uses, and their text in a liveliness token. The text has rmw_zenoh's
 * form {@code <reliability>:<durability>:<history>,<depth>:<deadline s>,<ns>:<lifespan s>,<ns>:<liveliness>,<s>,<ns>},
 * each field empty when it has the default value (reliable, volatile, keep last, no deadline,
 * no lifespan, automatic liveliness), so the default profile with depth 10 is
 * {@code ::,10:,:,:,,}. Immutable.
 *
 * @param reliable reliable (default) or best effort
 * @param transientLocal transient-local durability instead of volatile
 * @param depth the keep-last history depth
 */
public record QosProfile(boolean reliable, boolean transientLocal, int depth) {

    /** rmw's enumeration value of best-effort reliability. */
    private static final int BEST_EFFORT = 2;
    /** rmw's enumeration value of transient-local durability. */
    private static final int TRANSIENT_LOCAL = 1;

    /**
      * @param reliable reliable (default) or best effort
      * @param transientLocal transient-local durability instead of volatile
      * @param depth the keep-last history depth
     * @throws IllegalArgumentException if the depth is not positive
      */
    public QosProfile {
        if (depth <= 0) {
            throw new IllegalArgumentException("QoS history depth must be positive, got " + depth);
        }
    }

    /** @return ROS 2's default profile: reliable, volatile, keep last 10 */
    public static QosProfile defaults() {
        return new QosProfile(true, false, 10);
    }

    /** @return ROS 2's sensor-data profile: best effort, volatile, keep last 5 */
    public static QosProfile sensorData() {
        return new QosProfile(false, false, 5);
    }

    /**
     * The profile's text in a ROS 2 DDS bridge's route announcement ({@code zenoh-plugin-ros2dds}):
     * {@code :<reliability>:<durability>:<history>,<depth>} with Cyclone DDS's enumeration values
     * (best effort 0, reliable 1; volatile 0, transient local 1; keep last 0), the leading empty
     * field saying the type is keyless, as every ROS 2 message type is.
     *
     * @return the text
     */
    public String bridgeText() {
        return ":" + (reliable ? 1 : 0) + ":" + (transientLocal ? 1 : 0) + ":0," + depth;
    }

    /** @return the profile's text in a liveliness token */
    public String tokenText() {
        return (reliable ? "" : Integer.toString(BEST_EFFORT)) + ":" + (transientLocal ? Integer.toString(TRANSIENT_LOCAL) : "")
                + ":," + depth + ":,:,:,,";
    }
}
