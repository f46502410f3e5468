package io.rtaware.ros2msg;

import io.rtaware.ros2msg.value.PlanarTransform;
import java.util.List;

/**
 * The topics and frames of a mobile robot as rtaware records, exports and serves them: one place
 * for the names ROS 2 tools expect (REP 105 frames, the usual topic names) that the recorder's
 * robot plan, the ROS 2 exporter, the simulator's ROS 2 robot and its Foxglove feed all use.
 * Frames: {@value #MAP_FRAME} (the world, or the controller's map), {@value #ODOM_FRAME}
 * (odometry's origin), {@value #BASE_FRAME} (the robot's body), {@value #LASER_FRAME} (the laser,
 * at the robot's centre: the simulator's and the paper's Pioneer's scans are measured from there)
 * and {@value #GROUND_TRUTH_FRAME} (the true pose, a child of {@value #MAP_FRAME}). Stateless.
 */
public final class RobotTopics {

    /** The world's frame (REP 105), and the nav controller's map frame. */
    public static final String MAP_FRAME = "map";
    /** Odometry's frame (REP 105). */
    public static final String ODOM_FRAME = "odom";
    /** The robot's body frame (REP 105). */
    public static final String BASE_FRAME = "base_link";
    /** The laser's frame, a child of {@value #BASE_FRAME}. */
    public static final String LASER_FRAME = "laser";
    /** The true pose's frame, a child of {@value #MAP_FRAME} on {@value #TF}. */
    public static final String GROUND_TRUTH_FRAME = "ground_truth";

    /** Laser scans ({@code sensor_msgs/msg/LaserScan}, frame {@value #LASER_FRAME}). */
    public static final String SCAN = "/scan";
    /** Odometry ({@code nav_msgs/msg/Odometry}, frame {@value #ODOM_FRAME}, child {@value #BASE_FRAME}). */
    public static final String ODOM = "/odom";
    /** Velocity commands ({@code geometry_msgs/msg/Twist}). */
    public static final String CMD_VEL = "/cmd_vel";
    /** The true pose (frame {@value #MAP_FRAME}). */
    public static final String GROUND_TRUTH = "/ground_truth";
    /** An occupancy grid (frame {@value #MAP_FRAME}), latched. */
    public static final String MAP = "/map";
    /** A planned path (frame {@value #MAP_FRAME}). */
    public static final String PLAN = "/plan";
    /** Transforms that move ({@code tf2_msgs/msg/TFMessage}), as tf2 publishes them. */
    public static final String TF = "/tf";
    /** Transforms that do not move, latched, as tf2's static broadcaster publishes them. */
    public static final String TF_STATIC = "/tf_static";
    /** Simulated time ({@code rosgraph_msgs/msg/Clock}). */
    public static final String CLOCK = "/clock";

    /** {@value #BASE_FRAME} to {@value #LASER_FRAME}: the laser at the robot's centre. */
    public static final PlanarTransform LASER_MOUNT = new PlanarTransform(BASE_FRAME, LASER_FRAME, 0, 0, 0);
    /**
     * {@value #MAP_FRAME} to {@value #ODOM_FRAME}, the identity: the nav controller builds its map
     * in its odometry frame (no localization corrects odometry).
     */
    public static final PlanarTransform MAP_TO_ODOM = new PlanarTransform(MAP_FRAME, ODOM_FRAME, 0, 0, 0);
    /** What {@value #TF_STATIC} carries for a robot run: {@link #LASER_MOUNT} and {@link #MAP_TO_ODOM}. */
    public static final List<PlanarTransform> STATIC_TRANSFORMS = List.of(LASER_MOUNT, MAP_TO_ODOM);

    private RobotTopics() {
    }
}
