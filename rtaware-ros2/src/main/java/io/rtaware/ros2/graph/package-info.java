/**
 * The ROS 2 graph over Zenoh in the rmw_zenoh conventions (design document of ros2/rmw_zenoh,
 * 2025, Jazzy type hashes): topic key expressions {@code <domain>/<topic>/<dds type>/<RIHS01 hash>},
 * liveliness tokens that make nodes, publishers and subscriptions visible to {@code ros2 node
 * list} and {@code ros2 topic list}, the 33-byte attachment on every sample, and the QoS string
 * of tokens. A {@link io.rtaware.ros2.graph.Ros2Context} is one Zenoh session with its id
 * counter; {@link io.rtaware.ros2.graph.Ros2Node}s declare entities in it.
 */
package io.rtaware.ros2.graph;
