/**
 * The Foxglove WebSocket server ({@code --foxglove [HOST:]PORT}): the protocol foxglove_bridge
 * speaks (subprotocol {@code foxglove.websocket.v1}), fed by the recorder's writer thread as a
 * {@link io.rtaware.record.RecordingTap}, so that Foxglove connects to a running rtaware as to a
 * ROS 2 robot and sees the recording's channels, schemas and CDR messages live, the timing
 * channels beside the robot's. {@link io.rtaware.foxglove.FoxgloveProtocol} is the protocol's
 * messages, {@link io.rtaware.foxglove.FoxgloveServer} the server (Netty), and
 * {@link io.rtaware.foxglove.FoxgloveAddress} the flag's value.
 */
package io.rtaware.foxglove;
