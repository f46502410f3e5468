package io.rtaware.record;

import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.MediatorDecision;
import io.rtaware.robot.msg.OccupancyGrid;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.robot.msg.PlannedPath;
import io.rtaware.robot.msg.VelocityCommand;
import io.rtaware.ros2msg.LaserScanCodec;
import io.rtaware.ros2msg.OccupancyGridCodec;
import io.rtaware.ros2msg.OdometryCodec;
import io.rtaware.ros2msg.PathCodec;
import io.rtaware.ros2msg.PoseStampedCodec;
import io.rtaware.ros2msg.RobotTopics;
import io.rtaware.ros2msg.Ros2Codec;
import io.rtaware.ros2msg.TwistCodec;
import io.rtaware.ros2msg.value.PlanarPose;

/** Which value classes are recorded as which ROS 2 type (standard, or {@code rtaware_msgs} with named constants). */
public final class RosCodecs {

    private RosCodecs() {
    }

    /**
     * @param type a value class
     * @return a new codec for it (one per thread), or null if it has no standard ROS 2 type
     */
    public static Ros2Codec<?> forType(Class<?> type) {
        if (type == LaserScan.class) {
            return new LaserScanCodec();
        } else if (type == Odometry.class) {
            return new OdometryCodec(RobotTopics.BASE_FRAME);
        } else if (type == VelocityCommand.class) {
            return new TwistCodec();
        } else if (type == PlannedPath.class) {
            return new PathCodec();
        } else if (type == OccupancyGrid.class) {
            return new OccupancyGridCodec();
        } else if (type == PlanarPose.class) {
            return new PoseStampedCodec();
        } else if (type == MediatorDecision.class) {
            return new MediatorDecisionCodec();
        }
        return null;
    }
}
