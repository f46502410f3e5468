/**
 * A Player client over one TCP connection: {@link io.rtaware.player.client.PlayerClient}
 * checks the banner, matches requests to replies (with timeouts that name the device, since
 * Player stays silent about devices it lacks), switches between PUSH and PULL, subscribes,
 * sends velocity commands and keeps the newest odometry and scan it received, counting
 * messages, bytes, protocol errors and skipped messages in
 * {@link io.rtaware.player.client.PlayerCounters}.
 */
package io.rtaware.player.client;
