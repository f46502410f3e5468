package io.rtaware.ros2msg;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.OccupancyGrid;
import io.rtaware.robot.msg.PlannedPath;
import io.rtaware.ros2msg.cdr.CdrException;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.cdr.CdrWriter;
import io.rtaware.ros2msg.value.DiagnosticArray;
import io.rtaware.ros2msg.value.MetricsMessage;
import java.util.Arrays;
import org.junit.jupiter.api.Test;

/** Lengths from the wire are checked before anything is allocated or copied. */
class MalformedInputTest {

    private final CdrWriter writer = new CdrWriter(4096);
    private final CdrReader reader = new CdrReader();
    private final Ros2Header header = new Ros2Header().set(1, "laser");

    private byte[] scanBytes(int beams) {
        LaserScan scan = new LaserScan(beams);
        scan.setCount(beams);
        new LaserScanCodec().encode(header, scan, writer);
        return Arrays.copyOf(writer.buffer(), writer.size());
    }

    @Test
    void aSequenceLongerThanTheMessageIsRejected() {
        byte[] bytes = scanBytes(3);
        // after the encapsulation (4): stamp 8, frame_id length 4 and "laser\0" 6, padding to 20, 7 floats 28
        int lengthAt = 4 + 20 + 28;
        assertEquals(3, bytes[lengthAt]);
        bytes[lengthAt + 3] = 0x7f; // about two billion beams
        CdrException e = assertThrows(CdrException.class,
                () -> new LaserScanCodec().decode(reader.wrap(bytes, 0, bytes.length), header, new LaserScan(8)));
        assertTrue(e.getMessage().contains("exceeds"), e.getMessage());
    }

    @Test
    void moreBeamsThanTheTargetHoldsAreRejected() {
        byte[] bytes = scanBytes(10);
        CdrException e = assertThrows(CdrException.class,
                () -> new LaserScanCodec().decode(reader.wrap(bytes, 0, bytes.length), header, new LaserScan(4)));
        assertTrue(e.getMessage().contains("10 beams"), e.getMessage());
    }

    @Test
    void aTruncatedMessageIsRejected() {
        byte[] bytes = scanBytes(3);
        assertThrows(CdrException.class, () -> new LaserScanCodec()
                .decode(reader.wrap(bytes, 0, bytes.length - 5), header, new LaserScan(8)));
    }

    @Test
    void aStringLongerThanTheMessageIsRejected() {
        byte[] bytes = scanBytes(0);
        bytes[4 + 8] = (byte) 0xff; // frame_id length
        assertThrows(CdrException.class, () -> new LaserScanCodec()
                .decode(reader.wrap(bytes, 0, bytes.length), header, new LaserScan(8)));
    }

    @Test
    void bigEndianAndShortBuffersAreRejected() {
        assertThrows(CdrException.class, () -> reader.wrap(new byte[] {0, 0, 0, 0, 1}, 0, 5));
        assertThrows(CdrException.class, () -> reader.wrap(new byte[] {0, 1, 0}, 0, 3));
        assertThrows(CdrException.class, () -> reader.wrap(new byte[] {0, 1, 0, 0}, 2, 4));
    }

    @Test
    void aGridWhoseDataDisagreesWithItsSizeIsRejected() {
        OccupancyGrid grid = new OccupancyGrid(16);
        grid.setGeometry(4, 4, 0.1, 0, 0);
        new OccupancyGridCodec().encode(header, grid, writer);
        byte[] bytes = Arrays.copyOf(writer.buffer(), writer.size());
        assertThrows(CdrException.class, () -> new OccupancyGridCodec()
                .decode(reader.wrap(bytes, 0, bytes.length), header, new OccupancyGrid(8)));
    }

    @Test
    void pathsAndDiagnosticsBeyondCapacityAreRejected() {
        PlannedPath path = new PlannedPath(5);
        path.setCount(5);
        new PathCodec().encode(header, path, writer);
        byte[] bytes = Arrays.copyOf(writer.buffer(), writer.size());
        assertThrows(CdrException.class, () -> new PathCodec()
                .decode(reader.wrap(bytes, 0, bytes.length), header, new PlannedPath(4)));

        DiagnosticArray array = new DiagnosticArray(3, 1);
        array.add();
        array.add();
        new DiagnosticArrayCodec().encode(header, array, writer);
        byte[] diag = Arrays.copyOf(writer.buffer(), writer.size());
        assertThrows(CdrException.class, () -> new DiagnosticArrayCodec()
                .decode(reader.wrap(diag, 0, diag.length), header, new DiagnosticArray(1, 1)));
    }

    @Test
    void aMessageLargerThanTheWriterIsRefused() {
        LaserScan scan = new LaserScan(2000);
        scan.setCount(2000);
        assertThrows(CdrException.class, () -> new LaserScanCodec().encode(header, scan, new CdrWriter(1024)));
    }

    private byte[] metricsBytes(int points) {
        MetricsMessage m = new MetricsMessage(points);
        m.measurementSourceName.append("planner");
        for (int i = 0; i < points; i++) {
            m.add(MetricsMessage.AVERAGE, i);
        }
        new MetricsMessageCodec().encode(header, m, writer);
        return Arrays.copyOf(writer.buffer(), writer.size());
    }

    @Test
    void moreDataPointsThanTheTargetHoldsAreRejected() {
        byte[] bytes = metricsBytes(6);
        CdrException e = assertThrows(CdrException.class, () -> new MetricsMessageCodec()
                .decode(reader.wrap(bytes, 0, bytes.length), header, new MetricsMessage(5)));
        assertEquals("MetricsMessage of 6 data points exceeds the capacity of 5", e.getMessage());
    }

    @Test
    void anInfiniteStatisticIsNotEncoded() {
        MetricsMessage m = new MetricsMessage(5);
        m.measurementSourceName.append("planner");
        m.metricsSource.append("execution_time");
        m.add(MetricsMessage.AVERAGE, Double.NaN);
        m.add(MetricsMessage.MAXIMUM, Double.POSITIVE_INFINITY);
        CdrException e = assertThrows(CdrException.class, () -> new MetricsMessageCodec().encode(header, m, writer));
        assertEquals("MetricsMessage data point 1 of planner execution_time is Infinity: statistics are finite or NaN",
                e.getMessage());
    }
}
