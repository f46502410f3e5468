package io.rtaware.robot.msg;

import io.rtaware.core.data.StateValue;
import io.rtaware.robot.geometry.Pose2d;

/**
 * The robot's reported pose and velocity (Player position2d DATA STATE). Mutable buffer for
 * the data store; not thread-safe.
 */
public final class Odometry implements StateValue<Odometry> {

    /** x in metres, in the frame the robot server reports. */
    public double xM;
    /** y in metres. */
    public double yM;
    /** heading in radians. */
    public double yawRad;
    /** forward speed in m/s. */
    public double vxMps;
    /** sideways speed in m/s (0 for a differential drive). */
    public double vyMps;
    /** turn rate in rad/s. */
    public double omegaRadPerSec;
    /** true when the robot is pushing against an obstacle. */
    public boolean stall;
    /** the robot server's timestamp in seconds (simulated time with Stage or rtaware-sim). */
    public double serverTimeS;

    @Override
    public void copyFrom(Odometry s) {
        xM = s.xM;
        yM = s.yM;
        yawRad = s.yawRad;
        vxMps = s.vxMps;
        vyMps = s.vyMps;
        omegaRadPerSec = s.omegaRadPerSec;
        stall = s.stall;
        serverTimeS = s.serverTimeS;
    }

    /** @return the pose as an immutable value (allocates; not for hot paths) */
    public Pose2d pose() {
        return new Pose2d(xM, yM, yawRad);
    }
}
