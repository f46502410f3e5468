package io.rtaware.robotrun;

import io.rtaware.nav.NavController;
import io.rtaware.robot.msg.RobotKeys;
import io.rtaware.ros2.export.ExportedKey;
import io.rtaware.ros2msg.LaserScanCodec;
import io.rtaware.ros2msg.OccupancyGridCodec;
import io.rtaware.ros2msg.OdometryCodec;
import io.rtaware.ros2msg.PathCodec;
import io.rtaware.ros2msg.RobotTopics;
import io.rtaware.ros2msg.TwistCodec;
import java.util.List;

/**
 * The keys of a nav run that have a ROS 2 type, in their REP 105 frames, for the ROS 2 exporter
 * ({@code run --export}): odometry also as {@code odom} to {@code base_link} on {@code /tf}, the
 * occupancy grid and the planned path in {@code odom} (the controller builds and plans them on
 * odometry, without localization); on
 * {@code /tf_static} the exporter publishes {@link RobotTopics#STATIC_TRANSFORMS}, as recordings
 * do. Stateless.
 */
final class NavExports {

    private NavExports() {
    }

    /**
     * @param nav the controller whose keys are exported
     * @return laser, odometry, motor, the occupancy grid and the planned path with their types
     */
    static List<ExportedKey<?>> keys(NavController nav) {
        return List.of(
                new ExportedKey<>(RobotKeys.LASER, new LaserScanCodec(), RobotTopics.LASER_FRAME),
                new ExportedKey<>(RobotKeys.ODOMETRY, new OdometryCodec(RobotTopics.BASE_FRAME), RobotTopics.ODOM_FRAME,
                        RobotTopics.BASE_FRAME),
                new ExportedKey<>(RobotKeys.MOTOR, new TwistCodec(), ""),
                new ExportedKey<>(nav.keys().map(), new OccupancyGridCodec(), RobotTopics.ODOM_FRAME),
                new ExportedKey<>(nav.keys().path(), new PathCodec(), RobotTopics.ODOM_FRAME));
    }
}
