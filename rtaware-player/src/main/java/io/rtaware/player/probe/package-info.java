/**
 * {@link io.rtaware.player.probe.PlayerProbe}, the first thing a user runs against a new
 * robot: it connects, lists the server's devices and drivers, subscribes to position2d and
 * the scan source, and prints data rates and a few values.
 */
package io.rtaware.player.probe;
