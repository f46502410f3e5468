package io.rtaware.ros2msg;

import io.rtaware.robot.msg.VelocityCommand;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.cdr.CdrWriter;

/**
 * {@link VelocityCommand} as {@code geometry_msgs/msg/Twist}: linear (vx, 0, 0), angular
 * (0, 0, omega). The type has no header; decoding keeps linear.x and angular.z and ignores the
 * other components (a planar robot cannot follow them).
 */
public final class TwistCodec implements Ros2Codec<VelocityCommand> {

    @Override
    public Ros2MessageType type() {
        return Ros2Types.TWIST;
    }

    @Override
    public void encode(Ros2Header header, VelocityCommand value, CdrWriter out) {
        out.begin();
        Fields.writeVector3(out, value.vxMps, 0.0, 0.0);
        Fields.writeVector3(out, 0.0, 0.0, value.omegaRadPerSec);
    }

    @Override
    public void decode(CdrReader in, Ros2Header header, VelocityCommand into) {
        double vx = in.readFloat64();
        in.readFloat64();
        in.readFloat64();
        in.readFloat64();
        in.readFloat64();
        double omega = in.readFloat64();
        into.set(vx, omega);
    }
}
