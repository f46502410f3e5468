/**
 * The Player 3.x TCP protocol, written from its published facts: the 32-byte
 * {@link io.rtaware.player.protocol.Banner}, the 40-byte
 * {@link io.rtaware.player.protocol.PlayerHeader}, the message type, interface and subtype
 * codes, the body layouts of the player, position2d, laser, ranger and simulation interfaces
 * ({@link io.rtaware.player.protocol.PlayerCodec}, both directions, so a client and a server
 * share it) and {@link io.rtaware.player.protocol.PlayerFrameReader}, which cuts a byte
 * stream into messages, survives partial reads and rejects a bad size before allocating.
 */
package io.rtaware.player.protocol;
