/** Writing the occupancy grid the robot built in the formats other tools read. */
package io.rtaware.nav.map;
