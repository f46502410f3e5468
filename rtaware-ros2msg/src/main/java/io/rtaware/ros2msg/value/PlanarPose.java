package io.rtaware.ros2msg.value;

import io.rtaware.core.data.StateValue;
import io.rtaware.robot.geometry.Pose2d;

/**
 * A position and heading in the plane (a {@code geometry_msgs/msg/PoseStamped} without its
 * header, restricted to the plane). Mutable buffer; not thread-safe.
 */
public final class PlanarPose implements StateValue<PlanarPose> {

    /** x in metres. */
    public double xM;
    /** y in metres. */
    public double yM;
    /** heading in radians, counter-clockwise from +x. */
    public double yawRad;

    /**
     * @param x x in metres
     * @param y y in metres
     * @param yaw heading in radians
     */
    public void set(double x, double y, double yaw) {
        xM = x;
        yM = y;
        yawRad = yaw;
    }

    /** @param pose the pose to copy */
    public void set(Pose2d pose) {
        set(pose.xM(), pose.yM(), pose.yawRad());
    }

    @Override
    public void copyFrom(PlanarPose s) {
        set(s.xM, s.yM, s.yawRad);
    }
}
