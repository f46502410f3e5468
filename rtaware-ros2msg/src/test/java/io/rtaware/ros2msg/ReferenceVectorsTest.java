package io.rtaware.ros2msg;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.OccupancyGrid;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.robot.msg.PlannedPath;
import io.rtaware.robot.msg.VelocityCommand;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.cdr.CdrWriter;
import io.rtaware.ros2msg.value.DiagnosticArray;
import io.rtaware.ros2msg.value.DiagnosticStatus;
import io.rtaware.ros2msg.value.MetricsMessage;
import io.rtaware.ros2msg.value.PlanarPose;
import java.io.IOException;
import java.io.InputStream;
import java.util.HexFormat;
import java.util.Map;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * Definitions, type hashes and CDR bytes against vectors made by an independent serializer
 * (rosbags, see src/test/python/make_vectors.py): every sample encodes to exactly the reference
 * bytes, and decodes from them to the sample's values.
 */
class ReferenceVectorsTest {

    private static final Map<String, Ros2MessageType> TYPES = Map.of(
            "sensor_msgs/msg/LaserScan", Ros2Types.LASER_SCAN,
            "nav_msgs/msg/Odometry", Ros2Types.ODOMETRY,
            "geometry_msgs/msg/Twist", Ros2Types.TWIST,
            "nav_msgs/msg/Path", Ros2Types.PATH,
            "nav_msgs/msg/OccupancyGrid", Ros2Types.OCCUPANCY_GRID,
            "geometry_msgs/msg/PoseStamped", Ros2Types.POSE_STAMPED,
            "diagnostic_msgs/msg/DiagnosticArray", Ros2Types.DIAGNOSTIC_ARRAY,
            "statistics_msgs/msg/MetricsMessage", Ros2Types.METRICS_MESSAGE);

    private static JsonNode vectors;
    private final CdrWriter writer = new CdrWriter(1 << 16);
    private final CdrReader reader = new CdrReader();
    private final Ros2Header header = new Ros2Header();

    @BeforeAll
    static void load() throws IOException {
        try (InputStream in = ReferenceVectorsTest.class.getResourceAsStream("vectors.json")) {
            vectors = new ObjectMapper().readTree(in);
        }
    }

    private JsonNode entry(String type) {
        for (JsonNode t : vectors.get("types")) {
            if (t.get("type").asText().equals(type)) {
                return t;
            }
        }
        throw new AssertionError("no vectors for " + type);
    }

    @Test
    void everyTypeHasTheReferenceDefinitionHashAndDdsName() {
        assertEquals(TYPES.size(), vectors.get("types").size());
        for (JsonNode t : vectors.get("types")) {
            Ros2MessageType type = TYPES.get(t.get("type").asText());
            assertEquals(t.get("type").asText(), type.name());
            assertEquals(t.get("msgdef").asText(), type.schemaText(), type.name());
            assertEquals(t.get("rihs01").asText(), type.typeHash(), type.name());
        }
        assertEquals("sensor_msgs::msg::dds_::LaserScan_", Ros2Types.LASER_SCAN.ddsTypeName());
        assertEquals("geometry_msgs::msg::dds_::Twist_", Ros2Types.TWIST.ddsTypeName());
        assertEquals("diagnostic_msgs::msg::dds_::DiagnosticArray_", Ros2Types.DIAGNOSTIC_ARRAY.ddsTypeName());
    }

    private byte[] bytes(JsonNode sample) {
        return HexFormat.of().parseHex(sample.get("cdr_hex").asText());
    }

    private void header(JsonNode v) {
        header.set(v.get("stamp_ns").asLong(), v.get("frame_id").asText());
    }

    private void assertEncodes(byte[] expected, String what) {
        assertEquals(HexFormat.of().formatHex(expected),
                HexFormat.of().formatHex(writer.buffer(), 0, writer.size()), what);
    }

    private void assertHeader(JsonNode v) {
        assertEquals(v.get("stamp_ns").asLong(), header.stampNs);
        assertEquals(v.get("frame_id").asText(), header.frameId.toString());
    }

    @Test
    void laserScan() {
        LaserScanCodec codec = new LaserScanCodec();
        for (JsonNode s : entry("sensor_msgs/msg/LaserScan").get("samples")) {
            JsonNode v = s.get("values");
            LaserScan scan = new LaserScan(16);
            scan.minAngleRad = v.get("min_angle_rad").asDouble();
            scan.maxAngleRad = v.get("max_angle_rad").asDouble();
            scan.maxRangeM = v.get("max_range_m").asDouble();
            JsonNode ranges = v.get("ranges_m");
            scan.setCount(ranges.size());
            for (int i = 0; i < ranges.size(); i++) {
                scan.rangesM[i] = (float) ranges.get(i).asDouble();
            }
            header(v);
            codec.encode(header, scan, writer);
            byte[] expected = bytes(s);
            assertEncodes(expected, "LaserScan " + v);

            LaserScan back = new LaserScan(16);
            header.set(-1, "junk");
            codec.decode(reader.wrap(expected, 0, expected.length), header, back);
            assertHeader(v);
            assertEquals(scan.minAngleRad, back.minAngleRad);
            assertEquals(scan.maxAngleRad, back.maxAngleRad);
            assertEquals(scan.maxRangeM, back.maxRangeM);
            assertEquals(ranges.size(), back.count());
            for (int i = 0; i < ranges.size(); i++) {
                assertEquals(scan.rangesM[i], back.rangesM[i]);
            }
            assertEquals(v.get("stamp_ns").asLong() / 1e9, back.serverTimeS);
        }
    }

    @Test
    void odometry() {
        for (JsonNode s : entry("nav_msgs/msg/Odometry").get("samples")) {
            JsonNode v = s.get("values");
            OdometryCodec codec = new OdometryCodec(v.get("child_frame_id").asText());
            Odometry odo = new Odometry();
            odo.xM = v.get("x_m").asDouble();
            odo.yM = v.get("y_m").asDouble();
            odo.yawRad = v.get("yaw_rad").asDouble();
            odo.vxMps = v.get("vx_mps").asDouble();
            odo.vyMps = v.get("vy_mps").asDouble();
            odo.omegaRadPerSec = v.get("omega_rad_per_sec").asDouble();
            odo.stall = true;
            header(v);
            codec.encode(header, odo, writer);
            byte[] expected = bytes(s);
            assertEncodes(expected, "Odometry " + v);

            Odometry back = new Odometry();
            codec.decode(reader.wrap(expected, 0, expected.length), header, back);
            assertHeader(v);
            assertEquals(odo.xM, back.xM);
            assertEquals(odo.yM, back.yM);
            assertEquals(odo.yawRad, back.yawRad, 1e-15);
            assertEquals(odo.vxMps, back.vxMps);
            assertEquals(odo.vyMps, back.vyMps);
            assertEquals(odo.omegaRadPerSec, back.omegaRadPerSec);
            assertEquals(false, back.stall);
        }
    }

    @Test
    void twist() {
        TwistCodec codec = new TwistCodec();
        for (JsonNode s : entry("geometry_msgs/msg/Twist").get("samples")) {
            JsonNode v = s.get("values");
            VelocityCommand cmd = new VelocityCommand();
            cmd.set(v.get("vx_mps").asDouble(), v.get("omega_rad_per_sec").asDouble());
            codec.encode(header, cmd, writer);
            byte[] expected = bytes(s);
            assertEncodes(expected, "Twist " + v);
            VelocityCommand back = new VelocityCommand();
            codec.decode(reader.wrap(expected, 0, expected.length), header, back);
            assertEquals(cmd.vxMps, back.vxMps);
            assertEquals(cmd.omegaRadPerSec, back.omegaRadPerSec);
        }
    }

    @Test
    void path() {
        PathCodec codec = new PathCodec();
        for (JsonNode s : entry("nav_msgs/msg/Path").get("samples")) {
            JsonNode v = s.get("values");
            PlannedPath path = new PlannedPath(8);
            path.setCount(v.get("x_m").size());
            for (int i = 0; i < path.count(); i++) {
                path.xM[i] = v.get("x_m").get(i).asDouble();
                path.yM[i] = v.get("y_m").get(i).asDouble();
            }
            header(v);
            codec.encode(header, path, writer);
            byte[] expected = bytes(s);
            assertEncodes(expected, "Path " + v);
            PlannedPath back = new PlannedPath(8);
            codec.decode(reader.wrap(expected, 0, expected.length), header, back);
            assertHeader(v);
            assertEquals(path.count(), back.count());
            assertEquals(path.count() > 0, back.valid);
            for (int i = 0; i < path.count(); i++) {
                assertEquals(path.xM[i], back.xM[i]);
                assertEquals(path.yM[i], back.yM[i]);
            }
        }
    }

    @Test
    void occupancyGrid() {
        OccupancyGridCodec codec = new OccupancyGridCodec();
        for (JsonNode s : entry("nav_msgs/msg/OccupancyGrid").get("samples")) {
            JsonNode v = s.get("values");
            OccupancyGrid grid = new OccupancyGrid(64);
            grid.setGeometry(v.get("width").asInt(), v.get("height").asInt(), v.get("resolution_m").asDouble(),
                    v.get("origin_x_m").asDouble(), v.get("origin_y_m").asDouble());
            for (int i = 0; i < v.get("cells").size(); i++) {
                grid.cells[i] = (byte) v.get("cells").get(i).asInt();
            }
            header(v);
            codec.encode(header, grid, writer);
            byte[] expected = bytes(s);
            assertEncodes(expected, "OccupancyGrid " + v);
            OccupancyGrid back = new OccupancyGrid(64);
            codec.decode(reader.wrap(expected, 0, expected.length), header, back);
            assertHeader(v);
            assertEquals(grid.width(), back.width());
            assertEquals(grid.height(), back.height());
            assertEquals((float) grid.resolutionM, (float) back.resolutionM);
            assertEquals(grid.originXM, back.originXM);
            assertEquals(grid.originYM, back.originYM);
            for (int i = 0; i < grid.width() * grid.height(); i++) {
                assertEquals(grid.cells[i], back.cells[i]);
            }
        }
    }

    @Test
    void poseStamped() {
        PoseStampedCodec codec = new PoseStampedCodec();
        for (JsonNode s : entry("geometry_msgs/msg/PoseStamped").get("samples")) {
            JsonNode v = s.get("values");
            PlanarPose pose = new PlanarPose();
            pose.set(v.get("x_m").asDouble(), v.get("y_m").asDouble(), v.get("yaw_rad").asDouble());
            header(v);
            codec.encode(header, pose, writer);
            byte[] expected = bytes(s);
            assertEncodes(expected, "PoseStamped " + v);
            PlanarPose back = new PlanarPose();
            codec.decode(reader.wrap(expected, 0, expected.length), header, back);
            assertHeader(v);
            assertEquals(pose.xM, back.xM);
            assertEquals(pose.yM, back.yM);
            assertEquals(pose.yawRad, back.yawRad, 1e-15);
        }
    }

    @Test
    void diagnosticArray() {
        DiagnosticArrayCodec codec = new DiagnosticArrayCodec();
        for (JsonNode s : entry("diagnostic_msgs/msg/DiagnosticArray").get("samples")) {
            JsonNode v = s.get("values");
            DiagnosticArray array = new DiagnosticArray(4, 4);
            for (JsonNode st : v.get("status")) {
                DiagnosticStatus status = array.add();
                status.level = (byte) st.get("level").asInt();
                status.name.append(st.get("name").asText());
                status.message.append(st.get("message").asText());
                status.hardwareId.append(st.get("hardware_id").asText());
                for (JsonNode kv : st.get("values")) {
                    int k = status.addValue();
                    status.key(k).append(kv.get(0).asText());
                    status.value(k).append(kv.get(1).asText());
                }
            }
            header(v);
            codec.encode(header, array, writer);
            byte[] expected = bytes(s);
            assertEncodes(expected, "DiagnosticArray " + v);
            DiagnosticArray back = new DiagnosticArray(4, 4);
            codec.decode(reader.wrap(expected, 0, expected.length), header, back);
            assertHeader(v);
            assertEquals(array.count(), back.count());
            for (int i = 0; i < array.count(); i++) {
                DiagnosticStatus a = array.status(i);
                DiagnosticStatus b = back.status(i);
                assertEquals(a.level, b.level);
                assertEquals(a.name.toString(), b.name.toString());
                assertEquals(a.message.toString(), b.message.toString());
                assertEquals(a.hardwareId.toString(), b.hardwareId.toString());
                assertEquals(a.valueCount(), b.valueCount());
                for (int k = 0; k < a.valueCount(); k++) {
                    assertEquals(a.key(k).toString(), b.key(k).toString());
                    assertEquals(a.value(k).toString(), b.value(k).toString());
                }
            }
        }
    }

    @Test
    void metricsMessage() {
        MetricsMessageCodec codec = new MetricsMessageCodec();
        for (JsonNode s : entry("statistics_msgs/msg/MetricsMessage").get("samples")) {
            JsonNode v = s.get("values");
            MetricsMessage m = new MetricsMessage(8);
            m.measurementSourceName.append(v.get("measurement_source_name").asText());
            m.metricsSource.append(v.get("metrics_source").asText());
            m.unit.append(v.get("unit").asText());
            m.windowStartNs = v.get("window_start_ns").asLong();
            m.windowStopNs = v.get("window_stop_ns").asLong();
            for (JsonNode point : v.get("statistics")) {
                m.add((byte) point.get(0).asInt(), point.get(1).isNull() ? Double.NaN : point.get(1).asDouble());
            }
            codec.encode(header, m, writer);
            byte[] expected = bytes(s);
            assertEncodes(expected, "MetricsMessage " + v);
            MetricsMessage back = new MetricsMessage(8);
            codec.decode(reader.wrap(expected, 0, expected.length), header, back);
            assertEquals(m.measurementSourceName.toString(), back.measurementSourceName.toString());
            assertEquals(m.metricsSource.toString(), back.metricsSource.toString());
            assertEquals(m.unit.toString(), back.unit.toString());
            assertEquals(m.windowStartNs, back.windowStartNs);
            assertEquals(m.windowStopNs, back.windowStopNs);
            assertEquals(m.count(), back.count());
            for (int i = 0; i < m.count(); i++) {
                assertEquals(m.dataType(i), back.dataType(i));
                assertEquals(m.data(i), back.data(i)); // NaN equals NaN here, as Double.equals has it
            }
        }
    }
}
