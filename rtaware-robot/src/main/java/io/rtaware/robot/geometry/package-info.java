/** Plane geometry with units in every name: poses, points, angles. No I/O, no framework. */
package io.rtaware.robot.geometry;
