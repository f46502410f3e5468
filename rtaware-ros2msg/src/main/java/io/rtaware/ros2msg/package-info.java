/**
 * ROS 2 messages for rtaware: the definitions and RIHS01 type hashes of the standard types it
 * exchanges ({@link io.rtaware.ros2msg.Ros2Types}), and one {@link io.rtaware.ros2msg.Ros2Codec}
 * per type that encodes rtaware's robot data as CDR and decodes it back without allocating.
 * Used to record runs as MCAP and to talk to ROS 2 nodes.
 */
package io.rtaware.ros2msg;
