/**
 * The data task that connects a ROS 2 robot to the data store: {@link io.rtaware.ros2.task.Ros2DataTask}
 * subscribes {@code sensor_msgs/msg/LaserScan} and {@code nav_msgs/msg/Odometry}, publishes
 * {@code geometry_msgs/msg/Twist}, and commits to the same keys as the Player data task, so the
 * behaviors cannot tell the difference.
 */
package io.rtaware.ros2.task;
