/**
 * A world that moves: actors of a scenario ({@code actors:}) that the simulator puts into the
 * ground truth, the laser, collisions and the world picture. {@link io.rtaware.sim.actor.ActorSpec}
 * is what a scenario file says (a body moving along a polyline, a door that closes, an obstacle
 * that appears), {@link io.rtaware.sim.actor.ActorShape} its outline (a circle or a box), and
 * {@link io.rtaware.sim.actor.Actors} where every actor is at a world time, exactly (positions are
 * a closed-form function of time, not integrated).
 */
package io.rtaware.sim.actor;
