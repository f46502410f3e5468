package io.rtaware.player.protocol;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.fail;

import com.fasterxml.jackson.databind.JsonNode;
import io.rtaware.player.Captures;
import io.rtaware.player.xdr.XdrReader;
import io.rtaware.player.xdr.XdrWriter;
import io.rtaware.robot.msg.Odometry;
import java.io.ByteArrayInputStream;
import java.io.EOFException;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/** Decodes every message of both recorded sessions and compares with index.json. */
class CaptureDecodeTest {

    private static final double EPS = 1e-6;

    static List<String[]> streams() {
        return List.of(new String[] {"pull", "c2s"}, new String[] {"pull", "s2c"},
                new String[] {"push-with-ranger", "c2s"}, new String[] {"push-with-ranger", "s2c"});
    }

    @ParameterizedTest(name = "{0} {1}")
    @MethodSource("streams")
    void decodesEveryMessageLikeTheIndex(String session, String dir) throws Exception {
        byte[] stream = Captures.bytes(session, dir.equals("c2s") ? "client-to-server.bin" : "server-to-client.bin");
        List<JsonNode> expected = Captures.messages(session, dir);
        int start = 0;
        if (dir.equals("s2c")) {
            assertEquals("3.1.1-dev", Banner.decode(stream, Banner.SIZE_BYTES));
            start = Banner.SIZE_BYTES;
        }
        PlayerFrameReader frames = new PlayerFrameReader(start, PlayerFrameReader.DEFAULT_MAX_BODY_BYTES);
        ByteArrayInputStream in = new ByteArrayInputStream(stream, start, stream.length - start);
        LaserData laser = new LaserData(4096);
        RangerData ranger = new RangerData(4096);
        Odometry odo = new Odometry();
        for (JsonNode m : expected) {
            PlayerHeader h = frames.read(in);
            String where = session + " " + dir + " #" + m.get("n").asInt() + " " + m.get("summary").asText();
            assertEquals(m.get("offset").asLong(), frames.messageOffset(), where);
            assertEquals(m.get("length").asInt(), PlayerHeader.SIZE_BYTES + h.size(), where);
            JsonNode eh = m.get("header");
            assertEquals(eh.get("host").asLong(), h.host(), where);
            assertEquals(eh.get("robot").asLong(), h.robot(), where);
            assertEquals(eh.get("interf").asInt(), h.interf(), where);
            assertEquals(eh.get("index").asInt(), h.index(), where);
            assertEquals(eh.get("type").asInt(), h.type(), where);
            assertEquals(eh.get("subtype").asInt(), h.subtype(), where);
            assertEquals(eh.get("size").asInt(), h.size(), where);
            if (h.type() != MessageType.SYNCH) {
                assertEquals(eh.get("timestamp").asDouble(), h.timestampS(), 2e-6 * Math.max(1, h.timestampS()), where);
                assertEquals(eh.get("seq").asLong(), h.seq(), where);
            }
            checkBody(h, frames.body(), m.get("body"), where, laser, ranger, odo);
        }
        assertThrows(EOFException.class, () -> frames.read(in), "stream must end after the last indexed message");
    }

    private static void checkBody(PlayerHeader h, XdrReader r, JsonNode b, String where, LaserData laser,
                                  RangerData ranger, Odometry odo) throws Exception {
        int key = h.interf() * 10000 + h.subtype() * 10 + h.type();
        switch (h.interf()) {
            case Interfaces.PLAYER -> checkPlayer(h, r, b, where);
            case Interfaces.POSITION2D -> {
                if (h.type() == MessageType.DATA && h.subtype() == Subtypes.POSITION2D_DATA_STATE) {
                    PlayerCodec.readPosition2dState(r, odo);
                    assertEquals(b.get("pos").get("x").asDouble(), odo.xM, EPS, where);
                    assertEquals(b.get("pos").get("y").asDouble(), odo.yM, EPS, where);
                    assertEquals(b.get("pos").get("yaw").asDouble(), odo.yawRad, EPS, where);
                    assertEquals(b.get("vel").get("x").asDouble(), odo.vxMps, EPS, where);
                    assertEquals(b.get("vel").get("y").asDouble(), odo.vyMps, EPS, where);
                    assertEquals(b.get("vel").get("yaw").asDouble(), odo.omegaRadPerSec, EPS, where);
                    assertEquals(b.get("stall").asInt() != 0, odo.stall, where);
                } else if (h.type() == MessageType.CMD && h.subtype() == Subtypes.POSITION2D_CMD_VEL) {
                    VelocityCmd c = PlayerCodec.readVelocityCmd(r);
                    assertEquals(b.get("vel").get("x").asDouble(), c.vxMps(), EPS, where);
                    assertEquals(b.get("vel").get("y").asDouble(), c.vyMps(), EPS, where);
                    assertEquals(b.get("vel").get("yaw").asDouble(), c.omegaRadPerSec(), EPS, where);
                    assertEquals(b.get("state").asInt(), c.state(), where);
                } else if (h.subtype() == Subtypes.POSITION2D_REQ_GET_GEOM && h.type() == MessageType.REQ) {
                    assertEquals(0, r.remaining(), where);
                } else if (h.subtype() == Subtypes.POSITION2D_REQ_GET_GEOM && h.type() == MessageType.RESP_ACK) {
                    Geometry g = PlayerCodec.readGeometry(r);
                    Pose3d p = g.pose();
                    assertArrayEquals(doubles(b.get("pose_xyz_rpy")), new double[] {p.xM(), p.yM(), p.zM(),
                            p.rollRad(), p.pitchRad(), p.yawRad()}, EPS, where);
                    assertArrayEquals(doubles(b.get("size_wlh")), new double[] {g.size().widthM(),
                            g.size().lengthM(), g.size().heightM()}, EPS, where);
                } else {
                    fail("unexpected " + where + " key " + key);
                }
            }
            case Interfaces.LASER -> {
                assertEquals(MessageType.DATA, h.type(), where);
                assertEquals(Subtypes.LASER_DATA_SCAN, h.subtype(), where);
                PlayerCodec.readLaserScan(r, laser);
                assertEquals(b.get("min_angle").asDouble(), laser.minAngleRad, EPS, where);
                assertEquals(b.get("max_angle").asDouble(), laser.maxAngleRad, EPS, where);
                assertEquals(b.get("resolution").asDouble(), laser.resolutionRad, EPS, where);
                assertEquals(b.get("max_range").asDouble(), laser.maxRangeM, EPS, where);
                assertEquals(b.get("ranges_count").asInt(), laser.rangeCount, where);
                assertEquals(b.get("ranges_array_count").asInt(), laser.rangeCount, where);
                double[] first = doubles(b.get("first_ranges"));
                for (int i = 0; i < first.length; i++) {
                    assertEquals(first[i], laser.rangesM[i], EPS, where + " range " + i);
                }
                float min = Float.MAX_VALUE;
                for (int i = 0; i < laser.rangeCount; i++) {
                    min = Math.min(min, laser.rangesM[i]);
                }
                assertEquals(b.get("min_range_value").asDouble(), min, EPS, where);
                assertEquals(b.get("intensity_count").asInt(), laser.intensityCount, where);
                double[] firstI = doubles(b.get("intensity_first"));
                for (int i = 0; i < firstI.length; i++) {
                    assertEquals((int) firstI[i], laser.intensities[i] & 0xff, where + " intensity " + i);
                }
                assertEquals(b.get("id").asLong(), laser.id, where);
            }
            case Interfaces.RANGER -> {
                assertEquals(MessageType.DATA, h.type(), where);
                PlayerCodec.readRangerData(r, ranger);
                String prefix = h.subtype() == Subtypes.RANGER_DATA_RANGE ? "ranges" : "intensities";
                String firstKey = h.subtype() == Subtypes.RANGER_DATA_RANGE ? "first_ranges" : "first_intensities";
                assertEquals(b.get(prefix + "_count").asInt(), ranger.count, where);
                assertEquals(b.get(prefix + "_array_count").asInt(), ranger.count, where);
                double[] first = doubles(b.get(firstKey));
                assertArrayEquals(first, Arrays.copyOf(ranger.values, first.length), EPS, where);
            }
            default -> fail("unexpected interface in " + where);
        }
    }

    private static void checkPlayer(PlayerHeader h, XdrReader r, JsonNode b, String where) throws Exception {
        if (h.type() == MessageType.SYNCH) {
            assertEquals(0, PlayerCodec.readSynch(r), where);
            return;
        }
        switch (h.subtype()) {
            case Subtypes.PLAYER_REQ_DATAMODE -> {
                if (h.type() == MessageType.REQ) {
                    int mode = PlayerCodec.readDataMode(r);
                    assertEquals(b.get("mode").asText(), mode == Subtypes.DATAMODE_PUSH ? "PUSH" : "PULL", where);
                } else {
                    assertEquals(0, r.remaining(), where);
                }
            }
            case Subtypes.PLAYER_REQ_DEVLIST -> {
                List<DeviceAddress> list = PlayerCodec.readDeviceList(r);
                if (h.type() == MessageType.REQ) {
                    assertEquals(List.of(), list, where);
                } else {
                    assertEquals(b.get("devices_count").asInt(), list.size(), where);
                    for (int i = 0; i < list.size(); i++) {
                        DeviceAddress a = list.get(i);
                        assertEquals(b.get("devices").get(i).asText(),
                                a + " (host " + a.host() + " robot " + a.robot() + ")", where);
                    }
                }
            }
            case Subtypes.PLAYER_REQ_DRIVERINFO -> {
                DriverInfo info = PlayerCodec.readDriverInfo(r);
                assertEquals(b.get("addr").asText(), addr(info.device()), where);
                assertEquals(b.get("driver_name").asText(), info.driverName(), where);
                assertEquals(b.get("driver_name_count").asInt(), countOf(info.driverName()), where);
            }
            case Subtypes.PLAYER_REQ_DEV -> {
                DeviceRequest req = PlayerCodec.readDeviceRequest(r);
                assertEquals(b.get("addr").asText(), addr(req.device()), where);
                assertEquals(b.get("access").asText(), Subtypes.accessName(req.access()), where);
                assertEquals(b.get("driver_name").asText(), req.driverName(), where);
                assertEquals(b.get("driver_name_count").asInt(), countOf(req.driverName()), where);
            }
            case Subtypes.PLAYER_REQ_ADD_REPLACE_RULE -> {
                if (h.type() == MessageType.REQ) {
                    ReplaceRule rule = PlayerCodec.readReplaceRule(r);
                    assertEquals(new ReplaceRule(b.get("interf").asInt(), b.get("index").asInt(),
                            b.get("type").asInt(), b.get("subtype").asInt(), b.get("replace").asInt()), rule, where);
                } else {
                    assertEquals(0, r.remaining(), where);
                }
            }
            case Subtypes.PLAYER_REQ_DATA -> assertEquals(0, r.remaining(), where);
            default -> fail("unexpected " + where);
        }
    }

    private static int countOf(String name) {
        return name.isEmpty() ? 0 : name.length() + 1;
    }

    private static String addr(DeviceAddress a) {
        return a + " host=" + a.host() + " robot=" + a.robot();
    }

    private static double[] doubles(JsonNode array) {
        double[] d = new double[array.size()];
        for (int i = 0; i < d.length; i++) {
            d[i] = array.get(i).asDouble();
        }
        return d;
    }

    @ParameterizedTest(name = "{0} {1}")
    @MethodSource("streams")
    void reencodingEveryDecodedBodyGivesTheSameBytes(String session, String dir) throws Exception {
        byte[] stream = Captures.bytes(session, dir.equals("c2s") ? "client-to-server.bin" : "server-to-client.bin");
        int start = dir.equals("s2c") ? Banner.SIZE_BYTES : 0;
        PlayerFrameReader frames = new PlayerFrameReader(start, PlayerFrameReader.DEFAULT_MAX_BODY_BYTES);
        ByteArrayInputStream in = new ByteArrayInputStream(stream, start, stream.length - start);
        LaserData laser = new LaserData(4096);
        RangerData ranger = new RangerData(4096);
        Odometry odo = new Odometry();
        XdrWriter w = new XdrWriter();
        int count = Captures.messages(session, dir).size();
        for (int i = 0; i < count; i++) {
            PlayerHeader h = frames.read(in);
            XdrReader r = frames.body();
            w.reset();
            int at = PlayerCodec.beginMessage(w, h.address(), h.type(), h.subtype(), h.timestampS());
            encodeSame(h, r, w, laser, ranger, odo);
            PlayerCodec.endMessage(w, at);
            byte[] original = Arrays.copyOfRange(stream, (int) frames.messageOffset(),
                    (int) frames.messageOffset() + PlayerHeader.SIZE_BYTES + h.size());
            byte[] again = w.toByteArray();
            // seq is not part of beginMessage; SYNCH seq is garbage anyway
            System.arraycopy(original, 32, again, 32, 4);
            assertArrayEquals(original, again, session + " " + dir + " " + h);
        }
    }

    private static void encodeSame(PlayerHeader h, XdrReader r, XdrWriter w, LaserData laser, RangerData ranger,
                                   Odometry odo) throws Exception {
        if (h.size() == 0) {
            return;
        }
        if (h.interf() == Interfaces.PLAYER) {
            switch (h.subtype()) {
                case Subtypes.PLAYER_REQ_DATAMODE -> PlayerCodec.writeDataMode(w, PlayerCodec.readDataMode(r));
                case Subtypes.PLAYER_REQ_DEVLIST -> PlayerCodec.writeDeviceList(w, PlayerCodec.readDeviceList(r));
                case Subtypes.PLAYER_REQ_DRIVERINFO -> PlayerCodec.writeDriverInfo(w, PlayerCodec.readDriverInfo(r));
                case Subtypes.PLAYER_REQ_DEV -> PlayerCodec.writeDeviceRequest(w, PlayerCodec.readDeviceRequest(r));
                case Subtypes.PLAYER_REQ_ADD_REPLACE_RULE ->
                        PlayerCodec.writeReplaceRule(w, PlayerCodec.readReplaceRule(r));
                default -> fail("unexpected " + h);
            }
        } else if (h.interf() == Interfaces.POSITION2D) {
            if (h.type() == MessageType.DATA) {
                PlayerCodec.readPosition2dState(r, odo);
                PlayerCodec.writePosition2dState(w, odo);
            } else if (h.type() == MessageType.CMD) {
                VelocityCmd c = PlayerCodec.readVelocityCmd(r);
                PlayerCodec.writeVelocityCmd(w, c.vxMps(), c.vyMps(), c.omegaRadPerSec(), c.state());
            } else {
                PlayerCodec.writeGeometry(w, PlayerCodec.readGeometry(r));
            }
        } else if (h.interf() == Interfaces.LASER) {
            PlayerCodec.readLaserScan(r, laser);
            PlayerCodec.writeLaserScan(w, laser);
        } else if (h.interf() == Interfaces.RANGER) {
            PlayerCodec.readRangerData(r, ranger);
            PlayerCodec.writeRangerData(w, ranger);
        } else {
            fail("unexpected " + h);
        }
    }
}
