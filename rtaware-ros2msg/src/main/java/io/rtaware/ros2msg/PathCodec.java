package io.rtaware.ros2msg;

import io.rtaware.robot.msg.PlannedPath;
import io.rtaware.ros2msg.cdr.CdrException;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.cdr.CdrWriter;
import io.rtaware.ros2msg.value.PlanarPose;

/**
 * {@link PlannedPath} as {@code nav_msgs/msg/Path}: one {@code PoseStamped} per point, each
 * with the path's header and no rotation. The goal, cost and plan count have no fields in the
 * ROS type and are not carried. Decoding sets the points, marks the path valid when it has any,
 * and rejects more points than the target's capacity. One codec per thread (scratch pose).
 */
public final class PathCodec implements Ros2Codec<PlannedPath> {

    /** Least bytes of one PoseStamped on the wire: time 8 + string length 4 + NUL 1, pose 56. */
    private static final int MIN_POSE_STAMPED_BYTES = 8 + 4 + 1 + 56;

    private final PlanarPose scratch = new PlanarPose();

    @Override
    public Ros2MessageType type() {
        return Ros2Types.PATH;
    }

    @Override
    public void encode(Ros2Header header, PlannedPath value, CdrWriter out) {
        out.begin();
        Fields.writeHeader(out, header);
        int n = value.count();
        out.writeSequenceLength(n);
        for (int i = 0; i < n; i++) {
            Fields.writeHeader(out, header);
            Fields.writePlanarPose(out, value.xM[i], value.yM[i], 0.0);
        }
    }

    @Override
    public void decode(CdrReader in, Ros2Header header, PlannedPath into) {
        Fields.readHeader(in, header);
        int n = in.readSequenceLength(MIN_POSE_STAMPED_BYTES);
        if (n > into.capacity()) {
            throw new CdrException("Path of " + n + " poses exceeds the capacity of " + into.capacity());
        }
        for (int i = 0; i < n; i++) {
            Fields.skipHeader(in);
            Fields.readPlanarPose(in, scratch);
            into.xM[i] = scratch.xM;
            into.yM[i] = scratch.yM;
        }
        into.setCount(n);
        into.valid = n > 0;
    }
}
