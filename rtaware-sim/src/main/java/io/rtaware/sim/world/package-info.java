/**
 * The simulated robot: a Koala-like differential drive with collision handling, odometry and
 * a Hokuyo URG-04LX-like laser, stepped deterministically by {@link io.rtaware.sim.world.World#step(long)}.
 */
package io.rtaware.sim.world;
