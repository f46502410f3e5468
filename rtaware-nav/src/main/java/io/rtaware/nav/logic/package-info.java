/**
 * The navigation behaviors' pure logic: occupancy grid mapping with log-odds and ray tracing,
 * Dijkstra path planning on the grid, obstacle avoidance, pure-pursuit path following, waypoint
 * sequencing and the mediator's decision. No framework, no threads, no I/O; every class
 * preallocates its working memory so that a steady-state cycle allocates nothing, and none is
 * thread-safe (each is owned by one task).
 */
package io.rtaware.nav.logic;
