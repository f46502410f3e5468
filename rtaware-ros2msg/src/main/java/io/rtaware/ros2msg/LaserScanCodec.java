package io.rtaware.ros2msg;

import io.rtaware.robot.msg.LaserScan;
import io.rtaware.ros2msg.cdr.CdrException;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.cdr.CdrWriter;

/**
 * {@link LaserScan} as {@code sensor_msgs/msg/LaserScan}: {@code angle_min}/{@code angle_max}
 * are the first and last beam's bearings, {@code angle_increment} is (max - min) / (count - 1),
 * {@code range_min} 0, {@code range_max} the scan's maximum range, {@code time_increment} and
 * {@code scan_time} 0 (unknown), no intensities. Decoding keeps the angles, maximum range and
 * ranges, and sets the server time from the header stamp; a scan with more beams than the
 * target's capacity is rejected.
 */
public final class LaserScanCodec implements Ros2Codec<LaserScan> {

    @Override
    public Ros2MessageType type() {
        return Ros2Types.LASER_SCAN;
    }

    @Override
    public void encode(Ros2Header header, LaserScan value, CdrWriter out) {
        out.begin();
        Fields.writeHeader(out, header);
        out.writeFloat32((float) value.minAngleRad);
        out.writeFloat32((float) value.maxAngleRad);
        out.writeFloat32((float) value.angleIncrementRad());
        out.writeFloat32(0f);
        out.writeFloat32(0f);
        out.writeFloat32(0f);
        out.writeFloat32((float) value.maxRangeM);
        out.writeFloat32Sequence(value.rangesM, 0, value.count());
        out.writeSequenceLength(0);
    }

    @Override
    public void decode(CdrReader in, Ros2Header header, LaserScan into) {
        Fields.readHeader(in, header);
        double min = in.readFloat32();
        double max = in.readFloat32();
        in.readFloat32();
        in.readFloat32();
        in.readFloat32();
        in.readFloat32();
        double maxRange = in.readFloat32();
        int beams = in.readSequenceLength(4);
        if (beams > into.rangesM.length) {
            throw new CdrException("LaserScan of " + beams + " beams exceeds the capacity of " + into.rangesM.length);
        }
        for (int i = 0; i < beams; i++) {
            into.rangesM[i] = in.readFloat32();
        }
        int intensities = in.readSequenceLength(4);
        in.skip(intensities * 4);
        into.minAngleRad = min;
        into.maxAngleRad = max;
        into.maxRangeM = maxRange;
        into.serverTimeS = header.stampNs / 1e9;
        into.setCount(beams);
    }
}
