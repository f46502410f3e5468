/**
 * Occupancy-grid maps in the ROS {@code map_server} format (a YAML file naming a PGM or PNG
 * image) and the precomputed distance field used for O(1) collision checks and fast ray
 * casting.
 */
package io.rtaware.sim.map;
