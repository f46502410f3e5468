package io.rtaware.ros2.export;

import io.rtaware.core.data.Key;
import io.rtaware.core.data.StateValue;
import io.rtaware.ros2msg.Ros2Codec;

/**
 * A key of the data store with the ROS 2 type it is published as. Immutable.
 *
 * @param key the key
 * @param codec how its value becomes a ROS 2 message
 * @param frameId the frame id of the messages' headers
 * @param <T> the value type
 */
public record ExportedKey<T extends StateValue<T>>(Key<T> key, Ros2Codec<T> codec, String frameId) {

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
