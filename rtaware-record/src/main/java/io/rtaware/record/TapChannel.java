package io.rtaware.record;

/**
 * One channel of a recording as a {@link RecordingTap} sees it: the same topic, ROS 2 type and
 * {@code ros2msg} schema as the file's channel, with messages in {@value #MESSAGE_ENCODING}.
 *
 * @param id the channel's id (the file's channel id when there is a file), from 1
 * @param topic e.g. {@code /scan}
 * @param schemaName the ROS 2 type, e.g. {@code sensor_msgs/msg/LaserScan}
 * @param schema its {@code ros2msg} definition with its dependencies
 * @param latched its publisher offers transient-local durability ({@code /map}, {@code /tf_static}):
 *     a late subscriber is owed the last message
 */
public record TapChannel(int id, String topic, String schemaName, String schema, boolean latched) {

    /** The encoding of every channel's messages. */
    public static final String MESSAGE_ENCODING = "cdr";
    /** The encoding of every channel's schema. */
    public static final String SCHEMA_ENCODING = "ros2msg";
    /** The ROS 2 distribution whose message definitions the schemas are (as the bag metadata says). */
    public static final String ROS_DISTRO = Ros2Channels.ROS_DISTRO;
}
