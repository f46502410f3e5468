package io.rtaware.ros2msg;

import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.cdr.CdrWriter;
import io.rtaware.ros2msg.value.PlanarPose;

/**
 * {@link PlanarPose} as {@code geometry_msgs/msg/PoseStamped}: position (x, y, 0), rotation
 * about z by the heading. Decoding keeps x, y and the heading about z.
 */
public final class PoseStampedCodec implements Ros2Codec<PlanarPose> {

    @Override
    public Ros2MessageType type() {
        return Ros2Types.POSE_STAMPED;
    }

    @Override
    public void encode(Ros2Header header, PlanarPose value, CdrWriter out) {
        out.begin();
        Fields.writeHeader(out, header);
        Fields.writePlanarPose(out, value.xM, value.yM, value.yawRad);
    }

    @Override
    public void decode(CdrReader in, Ros2Header header, PlanarPose into) {
        Fields.readHeader(in, header);
        Fields.readPlanarPose(in, into);
    }
}
