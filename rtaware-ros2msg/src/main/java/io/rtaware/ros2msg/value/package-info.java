/**
 * Mutable, fixed-capacity values for the ROS 2 types that rtaware-robot has no type for (a
 * stamped planar pose, diagnostics), shaped like the robot data so that decoding into them
 * allocates nothing; and the immutable {@link io.rtaware.ros2msg.value.PlanarTransform} of
 * {@code /tf_static}.
 */
package io.rtaware.ros2msg.value;
