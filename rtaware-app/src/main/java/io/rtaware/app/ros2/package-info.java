/**
 * ROS 2 on the command line: the {@code --ros2} options of {@code run} and {@code sim}
 * ({@link io.rtaware.app.ros2.Ros2RunMixin}, {@link io.rtaware.app.ros2.Ros2SimMixin}) and the
 * wiring that opens Zenoh sessions, starts the simulator as a ROS 2 robot and builds the ROS 2
 * data task ({@link io.rtaware.app.ros2.Ros2Wiring#link}, a {@link io.rtaware.robotrun.Ros2Link}). Without the native Zenoh layer every
 * {@code --ros2} ends with one line saying how to enable it.
 */
package io.rtaware.app.ros2;
