/**
 * The simulator as a ROS 2 robot: {@link io.rtaware.sim.ros2.Ros2SimRobot} publishes the running
 * world's scans, odometry and ground truth and obeys Twist commands, over Zenoh in the rmw_zenoh
 * conventions, beside (not instead of) the Player server.
 */
package io.rtaware.sim.ros2;
