package io.rtaware.ros2.graph;

import io.rtaware.ros2msg.Ros2MessageType;
import java.util.Arrays;
import java.util.Locale;
import java.util.stream.Collectors;

/**
 * The ROS 2 distribution whose rmw_zenoh conventions a context follows. What differs between
 * them (read in rmw_zenoh's sources and release notes; docs/ros2.md lists the versions):
 * <ul>
 *   <li>the type hash in topic key expressions and liveliness tokens: Humble has no type
 *       hashes (its rosidl predates REP 2011), so rmw_zenoh writes {@code TypeHashNotSupported}
 *       there; Jazzy, Kilted and Rolling write the {@code RIHS01_<sha256>} hash;</li>
 *   <li>nothing else in the releases this targets: the 33-byte attachment (Humble from 0.1.2,
 *       Jazzy from 0.2.4, Kilted, Rolling from 0.6.0), the QoS text of a token and the gid
 *       (XXH3-128 of the entity's liveliness key, {@link Ros2Publisher#gid(String)}) are the
 *       same on all four.</li>
 * </ul>
 * Immutable.
 */
public enum Ros2Distro {

    /** ROS 2 Humble Hawksbill: rmw_zenoh 0.1.x from 0.1.2. */
    HUMBLE,
    /** ROS 2 Jazzy Jalisco: rmw_zenoh 0.2.x from 0.2.4. */
    JAZZY,
    /** ROS 2 Kilted Kaiju: rmw_zenoh 0.6.x. */
    KILTED,
    /** ROS 2 Rolling Ridley: rmw_zenoh from 0.6.0. */
    ROLLING;

    /** What rmw_zenoh writes for the type hash where the distribution has none (Humble). */
    public static final String TYPE_HASH_NOT_SUPPORTED = "TypeHashNotSupported";

    /** @return the distribution assumed when none is named: the newest released one, Kilted */
    public static Ros2Distro newest() {
        return KILTED;
    }

    /**
     * @param name {@code humble}, {@code jazzy}, {@code kilted} or {@code rolling} (any case)
     * @return the distribution
     * @throws IllegalArgumentException naming the value and the accepted ones
     */
    public static Ros2Distro parse(String name) {
        for (Ros2Distro d : values()) {
            if (d.cliName().equalsIgnoreCase(name == null ? "" : name.trim())) {
                return d;
            }
        }
        throw new IllegalArgumentException("unknown ROS 2 distribution '" + name + "' (expected one of "
                + Arrays.stream(values()).map(Ros2Distro::cliName).collect(Collectors.joining(", ")) + ")");
    }

    /** @return the distribution's name as ROS writes it, e.g. {@code jazzy} */
    public String cliName() {
        return name().toLowerCase(Locale.ROOT);
    }

    /**
     * @param type a message type
     * @return the type hash field of its key expressions and liveliness tokens in this
     *     distribution
     */
    public String typeHash(Ros2MessageType type) {
        return this == HUMBLE ? TYPE_HASH_NOT_SUPPORTED : type.typeHash();
    }
}
