/**
 * The Player TCP server of the simulator: serves {@code position2d:0}, {@code laser:0},
 * {@code ranger:0} and {@code simulation:0} of a {@link io.rtaware.sim.world.World} with the
 * rtaware-player codec, stepping the world on an injected clock or under a test's control.
 *
 * <p>Read {@link io.rtaware.sim.server.PlayerSimServer} first: it wires the accept loop and
 * client admission ({@code ClientAcceptor}), each client's connection ({@code ClientSession})
 * and what it is owed ({@code ClientQueue}, {@code ReplaceRules}), the routing of requests
 * ({@code RequestRouter}) to one {@code DeviceHandler} per device ({@code PlayerDevice},
 * {@code Position2dDevice}, {@code LaserDevice}, {@code RangerDevice},
 * {@code SimulationDevice}), and the stepping loop that publishes data ({@code WorldStepper}).
 */
package io.rtaware.sim.server;
