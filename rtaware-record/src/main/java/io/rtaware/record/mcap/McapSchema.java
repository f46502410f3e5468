package io.rtaware.record.mcap;

/**
 * A schema record.
 *
 * @param id schema id
 * @param name e.g. {@code sensor_msgs/msg/LaserScan}
 * @param encoding e.g. {@code ros2msg}
 * @param data the schema text (UTF-8)
 */
public record McapSchema(int id, String name, String encoding, String data) {
}
