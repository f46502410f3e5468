/**
 * The {@link io.rtaware.player.task.PlayerDataTask}: a continuous task that owns the Player
 * connection, publishes odometry and laser scans to the data store, sends the mediated motor
 * command (on change and as a keep-alive) and reconnects with back-off when asked to,
 * configured by an immutable {@link io.rtaware.player.task.PlayerConfig}.
 */
package io.rtaware.player.task;
