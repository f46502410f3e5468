/** Pictures of a scenario: map, obstacles, start, numbered waypoints, finish and driven paths. */
package io.rtaware.sim.render;
