package io.rtaware.ros2msg;

import static org.junit.jupiter.api.Assertions.assertEquals;

import io.rtaware.robot.msg.LaserScan;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.cdr.CdrWriter;
import org.junit.jupiter.api.Test;

/** What {@link LaserScanCodec} makes of the scans ROS 2 drivers send beside the usual ones. */
class LaserScanCodecTest {

    private final CdrWriter writer = new CdrWriter(1024);
    private final LaserScanCodec codec = new LaserScanCodec();

    /** A sensor_msgs/msg/LaserScan in CDR, field by field, as a driver would fill it. */
    private byte[] laserScan(float angleMin, float angleMax, float increment, float rangeMin, float rangeMax,
                             float... ranges) {
        writer.begin();
        writer.writeInt32(12); // stamp.sec
        writer.writeInt32(500_000_000); // stamp.nanosec
        writer.writeString("laser");
        writer.writeFloat32(angleMin);
        writer.writeFloat32(angleMax);
        writer.writeFloat32(increment);
        writer.writeFloat32(0f); // time_increment
        writer.writeFloat32(0.1f); // scan_time
        writer.writeFloat32(rangeMin);
        writer.writeFloat32(rangeMax);
        writer.writeFloat32Sequence(ranges, 0, ranges.length);
        writer.writeSequenceLength(0); // intensities
        byte[] bytes = new byte[writer.size()];
        System.arraycopy(writer.buffer(), 0, bytes, 0, bytes.length);
        return bytes;
    }

    private LaserScan decode(byte[] bytes) {
        LaserScan scan = new LaserScan(16);
        codec.decode(new CdrReader().wrap(bytes, 0, bytes.length), new Ros2Header(), scan);
        return scan;
    }

    @Test
    void aClockwiseScanIsReadAsTheSameBeamsCounterClockwise() {
        // Beam i at 1.0 - 0.5 i rad: +1.0 (left) reads 1 m, 0 reads 2 m, -1.0 (right) reads 3 m.
        LaserScan scan = decode(laserScan(1.0f, -1.0f, -0.5f, 0.02f, 4f, 1f, 1.5f, 2f, 2.5f, 3f));
        assertEquals(-1.0, scan.minAngleRad, 1e-6);
        assertEquals(1.0, scan.maxAngleRad, 1e-6);
        assertEquals(5, scan.count());
        assertEquals(3f, scan.rangesM[0], "the rightmost beam comes first");
        assertEquals(1f, scan.rangesM[4], "the leftmost last");
        assertEquals(-1.0, scan.bearingRad(0), 1e-6);
        assertEquals(5, scan.impliedBeams);
    }

    @Test
    void theMinimumRangeAndTheBeamsTheAnglesImplyAreKept() {
        LaserScan scan = decode(laserScan(-1.0f, 1.0f, 0.01f, 0.02f, 4f, Float.NEGATIVE_INFINITY));
        assertEquals(0.02, scan.minRangeM, 1e-6);
        assertEquals(201, scan.impliedBeams, "2 rad at 0.01 rad apart, both ends");
        assertEquals(1, scan.count());
        assertEquals(Float.NEGATIVE_INFINITY, scan.rangesM[0], "kept as sent: LaserScan defines what it means");
        assertEquals(12.5, scan.serverTimeS, 1e-9);
    }

    @Test
    void anIncrementOfZeroOrNotANumberImpliesNothing() {
        assertEquals(0, LaserScanCodec.impliedBeams(-1, 1, 0));
        assertEquals(0, LaserScanCodec.impliedBeams(-1, 1, Double.NaN));
        assertEquals(Integer.MAX_VALUE, LaserScanCodec.impliedBeams(-1, 1, 1e-30));
    }

    @Test
    void theMinimumRangeRoundTrips() {
        LaserScan scan = new LaserScan(4);
        scan.setCount(2);
        scan.minAngleRad = -0.5;
        scan.maxAngleRad = 0.5;
        scan.minRangeM = 0.02;
        scan.maxRangeM = 4;
        codec.encode(new Ros2Header().set(1_000_000_000L, "laser"), scan, writer);
        byte[] bytes = new byte[writer.size()];
        System.arraycopy(writer.buffer(), 0, bytes, 0, bytes.length);
        assertEquals(0.02, decode(bytes).minRangeM, 1e-6);
    }
}
