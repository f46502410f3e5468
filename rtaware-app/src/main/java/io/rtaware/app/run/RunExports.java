package io.rtaware.app.run;

import io.rtaware.nav.NavController;
import io.rtaware.record.RosCodecs;
import io.rtaware.robot.msg.RobotKeys;
import io.rtaware.ros2.export.ExportedKey;
import io.rtaware.ros2msg.LaserScanCodec;
import io.rtaware.ros2msg.OccupancyGridCodec;
import io.rtaware.ros2msg.OdometryCodec;
import io.rtaware.ros2msg.PathCodec;
import io.rtaware.ros2msg.TwistCodec;
import io.rtaware.ros2msg.value.PlanarTransform;
import java.util.List;

/**
 * The keys of a robot run that have a ROS 2 type, and its REP 105 frames, for
 * {@code run --export}: odometry also as {@code odom} to {@code base_link} on {@code /tf}, and
 * on {@code /tf_static} {@code base_link} to {@code laser} (the laser at the robot's centre) and
 * {@code map} to {@code odom} (the controller's map is its odometry frame), as in recordings.
 * Stateless.
 */
final class RunExports {

    /** What {@code /tf_static} carries. */
    static final List<PlanarTransform> STATIC_TRANSFORMS = List.of(
            new PlanarTransform(RosCodecs.BASE_FRAME, RunRecording.LASER_FRAME, 0, 0, 0),
            new PlanarTransform("map", "odom", 0, 0, 0));

    private RunExports() {
    }

    /**
     * @param nav the controller whose keys are exported
     * @return laser, odometry, motor, the occupancy grid and the planned path with their types
     */
    static List<ExportedKey<?>> keys(NavController nav) {
        return List.of(
                new ExportedKey<>(RobotKeys.LASER, new LaserScanCodec(), RunRecording.LASER_FRAME),
                new ExportedKey<>(RobotKeys.ODOMETRY, new OdometryCodec(RosCodecs.BASE_FRAME), "odom",
                        RosCodecs.BASE_FRAME),
                new ExportedKey<>(RobotKeys.MOTOR, new TwistCodec(), ""),
                new ExportedKey<>(nav.keys().map(), new OccupancyGridCodec(), "map"),
                new ExportedKey<>(nav.keys().path(), new PathCodec(), "map"));
    }
}
