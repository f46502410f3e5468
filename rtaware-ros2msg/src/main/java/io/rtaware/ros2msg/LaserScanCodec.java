package io.rtaware.ros2msg;

import io.rtaware.robot.msg.LaserScan;
import io.rtaware.ros2msg.cdr.CdrException;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.cdr.CdrWriter;

/**
 * {@link LaserScan} as {@code sensor_msgs/msg/LaserScan}: {@code angle_min}/{@code angle_max}
 * are the first and last beam's bearings, {@code angle_increment} is (max - min) / (count - 1),
 * {@code range_min} and {@code range_max} the scan's minimum and maximum range,
 * {@code time_increment} and {@code scan_time} 0 (unknown), no intensities. Decoding keeps the
 * angles, both ranges and the readings as sent (infinities included: {@link LaserScan} defines
 * them), sets the server time from the header stamp and {@link LaserScan#impliedBeams} from
 * the declared increment, and turns a scan swept clockwise (negative {@code angle_increment},
 * {@code angle_min > angle_max}) into the same beams in counter-clockwise order. A scan with
 * more beams than the target's capacity is rejected.
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
        out.writeFloat32((float) value.minRangeM);
        out.writeFloat32((float) value.maxRangeM);
        out.writeFloat32Sequence(value.rangesM, 0, value.count());
        out.writeSequenceLength(0);
    }

    @Override
    public void decode(CdrReader in, Ros2Header header, LaserScan into) {
        Fields.readHeader(in, header);
        double first = in.readFloat32();
        double last = in.readFloat32();
        double incrementRad = in.readFloat32();
        in.readFloat32(); // time_increment
        in.readFloat32(); // scan_time
        double minRange = in.readFloat32();
        double maxRange = in.readFloat32();
        int beams = in.readSequenceLength(4);
        if (beams > into.rangesM.length) {
            throw new CdrException("LaserScan of " + beams + " beams exceeds the capacity of " + into.rangesM.length);
        }
        float[] ranges = into.rangesM;
        for (int i = 0; i < beams; i++) {
            ranges[i] = in.readFloat32();
        }
        int intensities = in.readSequenceLength(4);
        in.skip(intensities * 4);
        boolean clockwise = incrementRad < 0;
        if (clockwise) {
            for (int i = 0, j = beams - 1; i < j; i++, j--) {
                float t = ranges[i];
                ranges[i] = ranges[j];
                ranges[j] = t;
            }
        }
        into.minAngleRad = clockwise ? last : first;
        into.maxAngleRad = clockwise ? first : last;
        into.minRangeM = minRange;
        into.maxRangeM = maxRange;
        into.impliedBeams = impliedBeams(first, last, incrementRad);
        into.serverTimeS = header.stampNs / 1e9;
        into.setCount(beams);
    }

    /**
     * @return the beams from {@code first} to {@code last} at {@code incrementRad} apart, end
     *     points included (at most {@link Integer#MAX_VALUE}); 0 when the increment is 0 or not a
     *     number (the scan does not say)
     */
    static int impliedBeams(double first, double last, double incrementRad) {
        if (incrementRad == 0 || Double.isNaN(incrementRad) || !Double.isFinite(first) || !Double.isFinite(last)) {
            return 0;
        }
        double steps = Math.abs((last - first) / incrementRad);
        return steps >= Integer.MAX_VALUE - 1 ? Integer.MAX_VALUE : (int) Math.round(steps) + 1;
    }
}
