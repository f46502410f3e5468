/**
 * Plausibility checks for robot data that enters from the network, shared by every data task
 * (Player, ROS 2): {@link io.rtaware.robot.validate.SampleChecks} holds the rules as pure
 * functions that return the reason a sample cannot be true (or null), {@link
 * io.rtaware.robot.validate.SampleValidator} applies them to one device's stream and counts
 * rejections, and {@link io.rtaware.robot.validate.RejectionWatch} turns persistent rejection
 * (a world-time span with only impossible samples) into a fault. A rejected sample is never
 * committed to the data store.
 */
package io.rtaware.robot.validate;
