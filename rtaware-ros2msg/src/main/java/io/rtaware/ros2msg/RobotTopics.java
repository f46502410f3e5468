package io.rtaware.ros2msg;

import io.rtaware.ros2msg.value.PlanarTransform;
import java.util.List;

/**
 * The topics and frames of a mobile robot as rtaware records, exports and serves them: one place
 * for the names ROS 2 tools expect (REP 105 frames, the usual topic names) that the recorder's
 * robot plan, the ROS 2 exporter, the simulator's ROS 2 robot and its Foxglove feed all use.
 *
 * <p>Frames, each with one meaning everywhere: {@value #ODOM_FRAME} (REP 105's odometry frame:
 * continuous, drifting; the nav controller has no localization, so it builds its map and plans
 * in this frame), {@value #BASE_FRAME} (the robot's body), {@value #LASER_FRAME} (the laser, at
 * the robot's centre: the simulator's and the paper's Pioneer's scans are measured from there),
 * {@value #WORLD_FRAME} (the simulated world's fixed frame, where the scenario's walls and
 * waypoints are given) and {@value #GROUND_TRUTH_FRAME} (the true pose, a child of
 * {@value #WORLD_FRAME}). No transform joins {@value #WORLD_FRAME} and {@value #ODOM_FRAME}: the
 * simulator starts odometry at the true start pose, so the two coincide at time 0 and part as
 * odometry drifts, by an amount only the truth knows. REP 105's {@code map} (a world-fixed frame
 * that localization keeps consistent with the world) is not used: nothing here localizes.
 * Stateless.
 */
public final class RobotTopics {

    /** The simulated world's fixed frame: the scenario's coordinates, where the true pose is given. */
    public static final String WORLD_FRAME = "world";
    /** Odometry's frame (REP 105), in which the nav controller builds its map and plans. */
    public static final String ODOM_FRAME = "odom";
    /** The robot's body frame (REP 105). */
    public static final String BASE_FRAME = "base_link";
    /** The laser's frame, a child of {@value #BASE_FRAME}. */
    public static final String LASER_FRAME = "laser";
    /** The true pose's frame, a child of {@value #WORLD_FRAME} on {@value #TF}. */
    public static final String GROUND_TRUTH_FRAME = "ground_truth";

    /** Laser scans ({@code sensor_msgs/msg/LaserScan}, frame {@value #LASER_FRAME}). */
    public static final String SCAN = "/scan";
    /** Odometry ({@code nav_msgs/msg/Odometry}, frame {@value #ODOM_FRAME}, child {@value #BASE_FRAME}). */
    public static final String ODOM = "/odom";
    /** Velocity commands ({@code geometry_msgs/msg/Twist}). */
    public static final String CMD_VEL = "/cmd_vel";
    /** The true pose (frame {@value #WORLD_FRAME}). */
    public static final String GROUND_TRUTH = "/ground_truth";
    /** An occupancy grid, latched: the nav controller's (frame {@value #ODOM_FRAME}), the simulator's walls (frame {@value #WORLD_FRAME}). */
    public static final String MAP = "/map";
    /** A planned path (the nav controller's, frame {@value #ODOM_FRAME}). */
    public static final String PLAN = "/plan";
    /** Transforms that move ({@code tf2_msgs/msg/TFMessage}), as tf2 publishes them. */
    public static final String TF = "/tf";
    /** Transforms that do not move, latched, as tf2's static broadcaster publishes them. */
    public static final String TF_STATIC = "/tf_static";
    /** Simulated time ({@code rosgraph_msgs/msg/Clock}). */
    public static final String CLOCK = "/clock";

    /** {@value #BASE_FRAME} to {@value #LASER_FRAME}: the laser at the robot's centre. */
    public static final PlanarTransform LASER_MOUNT = new PlanarTransform(BASE_FRAME, LASER_FRAME, 0, 0, 0);
    /** What {@value #TF_STATIC} carries for a robot run: {@link #LASER_MOUNT}. */
    public static final List<PlanarTransform> STATIC_TRANSFORMS = List.of(LASER_MOUNT);

    private RobotTopics() {
    }
}
