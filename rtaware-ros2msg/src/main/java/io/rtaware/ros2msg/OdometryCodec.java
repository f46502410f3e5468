package io.rtaware.ros2msg;

import io.rtaware.robot.msg.Odometry;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.cdr.CdrWriter;
import io.rtaware.ros2msg.value.PlanarPose;

/**
 * {@link Odometry} as {@code nav_msgs/msg/Odometry}: pose (x, y, 0) with a rotation about z by
 * the heading, twist linear (vx, vy, 0) and angular (0, 0, omega), covariances zero (unknown),
 * {@code child_frame_id} given at construction. The stall flag has no field in the ROS type and
 * is not carried; decoding sets it false and the server time from the header stamp. Decoding
 * keeps state in a scratch pose: one codec per thread.
 */
public final class OdometryCodec implements Ros2Codec<Odometry> {

    private static final int COVARIANCE_SIZE = 36;

    private final String childFrameId;
    private final PlanarPose scratch = new PlanarPose();

    /** @param childFrameId the frame the twist is expressed in, e.g. {@code base_link} */
    public OdometryCodec(String childFrameId) {
        this.childFrameId = childFrameId;
    }

    @Override
    public Ros2MessageType type() {
        return Ros2Types.ODOMETRY;
    }

    @Override
    public void encode(Ros2Header header, Odometry value, CdrWriter out) {
        out.begin();
        Fields.writeHeader(out, header);
        out.writeString(childFrameId);
        Fields.writePlanarPose(out, value.xM, value.yM, value.yawRad);
        out.writeFloat64Repeated(0.0, COVARIANCE_SIZE);
        Fields.writeVector3(out, value.vxMps, value.vyMps, 0.0);
        Fields.writeVector3(out, 0.0, 0.0, value.omegaRadPerSec);
        out.writeFloat64Repeated(0.0, COVARIANCE_SIZE);
    }

    @Override
    public void decode(CdrReader in, Ros2Header header, Odometry into) {
        Fields.readHeader(in, header);
        in.skipString();
        Fields.readPlanarPose(in, scratch);
        for (int i = 0; i < COVARIANCE_SIZE; i++) {
            in.readFloat64();
        }
        double vx = in.readFloat64();
        double vy = in.readFloat64();
        in.readFloat64();
        in.readFloat64();
        in.readFloat64();
        double omega = in.readFloat64();
        for (int i = 0; i < COVARIANCE_SIZE; i++) {
            in.readFloat64();
        }
        into.xM = scratch.xM;
        into.yM = scratch.yM;
        into.yawRad = scratch.yawRad;
        into.vxMps = vx;
        into.vyMps = vy;
        into.omegaRadPerSec = omega;
        into.stall = false;
        into.serverTimeS = header.stampNs / 1e9;
    }
}
