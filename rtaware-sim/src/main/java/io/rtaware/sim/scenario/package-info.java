/**
 * Scenarios: the map, start pose, waypoints, goal tolerance and time limit of one run, loaded
 * from YAML files or from the built-in {@code paper-room}.
 */
package io.rtaware.sim.scenario;
