package io.rtaware.app.run;

import io.rtaware.nav.NavController;
import io.rtaware.robot.msg.RobotKeys;
import io.rtaware.ros2.export.ExportedKey;
import io.rtaware.ros2msg.LaserScanCodec;
import io.rtaware.ros2msg.OccupancyGridCodec;
import io.rtaware.ros2msg.OdometryCodec;
import io.rtaware.ros2msg.PathCodec;
import io.rtaware.ros2msg.TwistCodec;
import java.util.List;

/** The keys of a robot run that have a ROS 2 type, for {@code run --export}. Stateless. */
final class RunExports {

    private RunExports() {
    }

    /**
     * @param nav the controller whose keys are exported
     * @return laser, odometry, motor, the occupancy grid and the planned path with their types
     */
    static List<ExportedKey<?>> keys(NavController nav) {
        return List.of(
                new ExportedKey<>(RobotKeys.LASER, new LaserScanCodec(), "laser"),
                new ExportedKey<>(RobotKeys.ODOMETRY, new OdometryCodec("base_link"), "odom"),
                new ExportedKey<>(RobotKeys.MOTOR, new TwistCodec(), ""),
                new ExportedKey<>(nav.keys().map(), new OccupancyGridCodec(), "map"),
                new ExportedKey<>(nav.keys().path(), new PathCodec(), "map"));
    }
}
