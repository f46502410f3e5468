package io.rtaware.ros2.export;

import io.rtaware.core.data.Key;
import io.rtaware.core.data.StateValue;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.ros2msg.Ros2Codec;

/**
 * A key of the data store with the ROS 2 type it is published as. Immutable.
 *
 * @param key the key
 * @param codec how its value becomes a ROS 2 message
 * @param frameId the frame id of the messages' headers
 * @param transformChild for an odometry key, the child frame of the transform each published
 *     value also makes on {@code /tf} ({@code frameId} to it, REP 105: {@code odom} to
 *     {@code base_link}); null for none
 * @param <T> the value type
 */
public record ExportedKey<T extends StateValue<T>>(Key<T> key, Ros2Codec<T> codec, String frameId,
                                                   String transformChild) {

    /**
     * A key published without a transform.
     *
     * @param key the key
     * @param codec how its value becomes a ROS 2 message
     * @param frameId the frame id of the messages' headers
     */
    public ExportedKey(Key<T> key, Ros2Codec<T> codec, String frameId) {
        this(key, codec, frameId, null);
    }

    /**
     * @param key the key
     * @param codec how its value becomes a ROS 2 message
     * @param frameId the frame id of the messages' headers
     * @param transformChild the child frame of the transform each value makes on {@code /tf}, or null
     * @throws IllegalArgumentException if a transform is asked of a key that is not odometry
     */
    public ExportedKey {
        if (transformChild != null && !Odometry.class.equals(key.type())) {
            throw new IllegalArgumentException("only odometry makes transforms, not key " + key.name() + " of "
                    + key.type().getSimpleName());
        }
    }

    /**
     * @return the topic the key is published on: {@code /rtaware/} and the key's name with
     *     every character that a ROS 2 name does not allow replaced by {@code _}
     */
    public String topic() {
        return topicOf(key.name());
    }

    /**
     * @param keyName a key's name
     * @return its topic under {@code /rtaware}
     */
    public static String topicOf(String keyName) {
        String name = keyName.replaceAll("[^A-Za-z0-9_]", "_");
        return "/rtaware/" + (Character.isDigit(name.charAt(0)) ? "_" + name : name);
    }
}
