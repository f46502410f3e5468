package io.rtaware.ros2msg;

import io.rtaware.robot.msg.OccupancyGrid;
import io.rtaware.ros2msg.cdr.CdrException;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.cdr.CdrWriter;
import io.rtaware.ros2msg.value.PlanarPose;

/**
 * {@link OccupancyGrid} as {@code nav_msgs/msg/OccupancyGrid}: the cell layout is the same
 * (row 0 at the lowest y, -1 unknown, 0 free, 100 occupied); the origin is the lower-left corner
 * without rotation, {@code map_load_time} the header stamp, the resolution a float32. Decoding
 * rejects a grid whose data length differs from width x height or exceeds the target's
 * capacity (a rotated origin is not representable and its rotation is dropped). One codec per
 * thread (scratch pose).
 */
public final class OccupancyGridCodec implements Ros2Codec<OccupancyGrid> {

    private final PlanarPose scratch = new PlanarPose();

    @Override
    public Ros2MessageType type() {
        return Ros2Types.OCCUPANCY_GRID;
    }

    @Override
    public void encode(Ros2Header header, OccupancyGrid value, CdrWriter out) {
        out.begin();
        Fields.writeHeader(out, header);
        Fields.writeTime(out, header.stampNs);
        out.writeFloat32((float) value.resolutionM);
        out.writeInt32(value.width());
        out.writeInt32(value.height());
        Fields.writePlanarPose(out, value.originXM, value.originYM, 0.0);
        out.writeInt8Sequence(value.cells, 0, value.width() * value.height());
    }

    @Override
    public void decode(CdrReader in, Ros2Header header, OccupancyGrid into) {
        Fields.readHeader(in, header);
        Fields.readTime(in);
        double resolution = in.readFloat32();
        long width = in.readInt32() & 0xffffffffL;
        long height = in.readInt32() & 0xffffffffL;
        Fields.readPlanarPose(in, scratch);
        int cells = in.readSequenceLength(1);
        if (width * height != cells) {
            throw new CdrException("OccupancyGrid of " + width + " x " + height + " cells carries " + cells);
        }
        if (cells > into.cells.length || width > into.cells.length || height > into.cells.length) {
            // A side longer than the capacity is refused even when the other side is 0 (found by fuzzing).
            throw new CdrException("OccupancyGrid of " + width + " x " + height + " cells exceeds the capacity of "
                    + into.cells.length);
        }
        in.readBytes(into.cells, 0, cells);
        into.setGeometry((int) width, (int) height, resolution, scratch.xM, scratch.yM);
    }
}
