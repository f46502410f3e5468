/**
 * The Player TCP server of the simulator: serves {@code position2d:0}, {@code laser:0},
 * {@code ranger:0} and {@code simulation:0} of a {@link io.rtaware.sim.world.World} with the
 * rtaware-player codec, stepping the world on an injected clock or under a test's control.
 */
package io.rtaware.sim.server;
