package io.rtaware.player.client;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import io.rtaware.player.Captures;
import io.rtaware.player.ScriptedServer;
import io.rtaware.player.protocol.Banner;
import io.rtaware.player.protocol.DeviceAddress;
import io.rtaware.player.protocol.Geometry;
import io.rtaware.player.protocol.Interfaces;
import io.rtaware.player.protocol.LaserConfig;
import io.rtaware.player.protocol.MessageType;
import io.rtaware.player.protocol.PlayerCodec;
import io.rtaware.player.protocol.PlayerHeader;
import io.rtaware.player.protocol.RangerConfig;
import io.rtaware.player.protocol.RangerData;
import io.rtaware.player.protocol.ReplaceRule;
import io.rtaware.player.protocol.SimulationPose2d;
import io.rtaware.player.protocol.Subtypes;
import io.rtaware.player.xdr.PlayerProtocolException;
import io.rtaware.player.xdr.XdrReader;
import io.rtaware.player.xdr.XdrWriter;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The client against a scripted server on 127.0.0.1 replaying the captures. */
@Timeout(30)
class PlayerClientTest {

    private static final String LOCAL = "127.0.0.1";

    private static PlayerClientOptions options(int requestTimeoutMs) {
        return new PlayerClientOptions(2000, requestTimeoutMs, 1 << 20, 4096);
    }

    /** Replays a session: checks every client message byte for byte, answers with the capture. */
    private static ScriptedServer replay(String session, int chunk) throws Exception {
        byte[] s2c = Captures.bytes(session, "server-to-client.bin");
        byte[] c2s = Captures.bytes(session, "client-to-server.bin");
        List<JsonNode> index = Captures.index(session);
        return new ScriptedServer(conn -> {
            conn.chunks(chunk);
            for (JsonNode m : index) {
                int off = m.get("offset").asInt();
                int len = m.get("length").asInt();
                if (m.get("dir").asText().equals("s2c")) {
                    conn.send(s2c, off, len);
                } else {
                    byte[] got = conn.readMessage();
                    byte[] want = Arrays.copyOfRange(c2s, off, off + len);
                    if (!ScriptedServer.sameIgnoringHostRobotTime(got, want)) {
                        throw new AssertionError("client message differs from libplayerc's for " + m.get("summary")
                                + "\n got  " + hex(got) + "\n want " + hex(want));
                    }
                }
            }
            if (!conn.clientClosed()) {
                throw new AssertionError("client sent more than libplayerc did");
            }
        });
    }

    private static String hex(byte[] b) {
        StringBuilder sb = new StringBuilder();
        for (byte x : b) {
            sb.append(String.format("%02x", x));
        }
        return sb.toString();
    }

    /** Performs, with our client, what libplayerc did at each of its messages. */
    private static void drive(String session, PlayerClient client) throws Exception {
        List<DeviceAddress> devices = List.of();
        for (JsonNode m : Captures.messages(session, "c2s")) {
            JsonNode h = m.get("header");
            JsonNode b = m.get("body");
            int interf = h.get("interf").asInt();
            int type = h.get("type").asInt();
            int subtype = h.get("subtype").asInt();
            if (type == MessageType.CMD) {
                client.sendVelocity(h.get("index").asInt(), b.get("vel").get("x").asDouble(),
                        b.get("vel").get("y").asDouble(), b.get("vel").get("yaw").asDouble(), b.get("state").asInt());
            } else if (interf == Interfaces.POSITION2D) {
                Geometry g = client.position2dGeometry(0);
                assertEquals(0.44, g.size().lengthM(), 1e-9);
            } else {
                switch (subtype) {
                    case Subtypes.PLAYER_REQ_DATAMODE -> client.setDataMode(
                            b.get("mode").asText().equals("PUSH") ? Subtypes.DATAMODE_PUSH : Subtypes.DATAMODE_PULL);
                    case Subtypes.PLAYER_REQ_ADD_REPLACE_RULE -> client.addReplaceRule(ReplaceRule.latestDataOnly());
                    case Subtypes.PLAYER_REQ_DEVLIST -> {
                        devices = client.deviceList();
                        assertEquals(4, devices.size());
                    }
                    case Subtypes.PLAYER_REQ_DRIVERINFO -> {
                        DeviceAddress want = DeviceAddress.parse(b.get("addr").asText().split(" ")[0]);
                        DeviceAddress dev = devices.stream().filter(want::sameDevice).findFirst().orElseThrow();
                        String driver = client.driverInfo(dev);
                        assertEquals(dev.interf() == Interfaces.LASER ? "rangertolaser" : "stage", driver);
                    }
                    case Subtypes.PLAYER_REQ_DEV -> {
                        DeviceAddress dev = DeviceAddress.parse(b.get("addr").asText().split(" ")[0]);
                        if (b.get("access").asText().equals("OPEN")) {
                            if (dev.interf() == Interfaces.PLANNER) {
                                PlayerNackException e = assertThrows(PlayerNackException.class,
                                        () -> client.subscribe(dev));
                                assertTrue(e.getMessage().contains("planner:0"), e.getMessage());
                            } else {
                                assertEquals(Subtypes.ACCESS_OPEN, client.subscribe(dev).access());
                            }
                        } else {
                            assertEquals(Subtypes.ACCESS_CLOSE, client.unsubscribe(dev).access());
                        }
                    }
                    case Subtypes.PLAYER_REQ_DATA -> {
                        client.requestData();
                        long before = client.synchs();
                        client.poll(5000, true);
                        assertEquals(before + 1, client.synchs());
                    }
                    default -> throw new AssertionError("unexpected " + m.get("summary"));
                }
            }
        }
    }

    @ParameterizedTest(name = "{0}, chunks up to {1} bytes")
    @CsvSource({"pull, 2147483647", "pull, 1", "push-with-ranger, 2147483647", "push-with-ranger, 7"})
    void replaysTheCapturedSessionSendingWhatLibplayercSent(String session, int chunk) throws Exception {
        try (ScriptedServer server = replay(session, chunk)) {
            PlayerCounters counters = new PlayerCounters();
            try (PlayerClient client = PlayerClient.connect(LOCAL, server.port(), options(5000), counters)) {
                assertEquals("3.1.1-dev", client.serverVersion());
                drive(session, client);
                if (session.equals("pull")) {
                    assertEquals(60, client.odometryUpdates());
                    assertEquals(120, client.laserUpdates());
                    assertEquals(60, client.synchs());
                    assertEquals(0, counters.snapshot().skippedMessages());
                } else {
                    assertEquals(60, client.odometryUpdates());
                    assertEquals(60, client.laserUpdates());
                    assertEquals(120, counters.snapshot().skippedMessages(), "ranger data without config is skipped");
                }
                assertEquals(241, client.laserScan().count());
                assertEquals(-2.094395, client.laserScan().minAngleRad, 1e-6);
                assertEquals(Math.toRadians(1.0), client.laserScan().angleIncrementRad(), 1e-6);
                assertEquals(0, counters.snapshot().protocolErrors());
            }
            server.await();
            PlayerStats stats = counters.snapshot();
            byte[] s2c = Captures.bytes(session, "server-to-client.bin");
            byte[] c2s = Captures.bytes(session, "client-to-server.bin");
            assertEquals(s2c.length, stats.bytesReceived());
            assertEquals(c2s.length, stats.bytesSent());
        }
    }

    @Test
    void silentServerGivesARequestTimeoutNamingTheDevice() throws Exception {
        try (ScriptedServer server = new ScriptedServer(conn -> {
            conn.banner();
            conn.readMessage();
            conn.clientClosed();
        })) {
            try (PlayerClient client = PlayerClient.connect(LOCAL, server.port(), options(300), new PlayerCounters())) {
                PlayerTimeoutException e = assertThrows(PlayerTimeoutException.class, () -> client.laserConfig(0));
                assertTrue(e.getMessage().contains("laser:0") && e.getMessage().contains("300 ms"), e.getMessage());
            }
            server.await();
        }
    }

    @Test
    void serverClosingMidRunGivesAConnectionError() throws Exception {
        byte[] s2c = Captures.bytes("pull", "server-to-client.bin");
        try (ScriptedServer server = new ScriptedServer(conn -> {
            conn.banner();
            conn.send(s2c, 792, 92); // one position2d state
            conn.close();
        })) {
            try (PlayerClient client = PlayerClient.connect(LOCAL, server.port(), options(1000), new PlayerCounters())) {
                PlayerConnectionException e = assertThrows(PlayerConnectionException.class, () -> {
                    while (true) {
                        client.poll(1000, false);
                    }
                });
                assertTrue(e.getMessage().contains("closed the connection"), e.getMessage());
                assertEquals(1, client.odometryUpdates());
            }
            server.await();
        }
    }

    @Test
    void serverClosingInsideAMessageIsAProtocolError() throws Exception {
        byte[] s2c = Captures.bytes("pull", "server-to-client.bin");
        try (ScriptedServer server = new ScriptedServer(conn -> {
            conn.banner();
            conn.send(s2c, 884, 500); // half a laser scan
            conn.close();
        })) {
            try (PlayerClient client = PlayerClient.connect(LOCAL, server.port(), options(1000), new PlayerCounters())) {
                PlayerProtocolException e = assertThrows(PlayerProtocolException.class, () -> {
                    while (true) {
                        client.poll(1000, false);
                    }
                });
                assertTrue(e.getMessage().contains("stream ended after 500 of 1040"), e.getMessage());
            }
            server.await();
        }
    }

    @Test
    void nonPlayerPeerIsNamedInTheError() throws Exception {
        try (ScriptedServer server = new ScriptedServer(conn -> {
            conn.send("HTTP/1.1 400 Bad Request\r\n\r\n<html>".getBytes(StandardCharsets.US_ASCII));
            conn.clientClosed();
        })) {
            PlayerProtocolException e = assertThrows(PlayerProtocolException.class,
                    () -> PlayerClient.connect(LOCAL, server.port(), options(1000), new PlayerCounters()));
            assertTrue(e.getMessage().contains("not a Player server") && e.getMessage().contains("HTTP/1.1 400")
                    && e.getMessage().contains("\\x0d\\x0a"), e.getMessage());
            server.await();
        }
    }

    @Test
    void shortSilentBannerIsNamedInTheError() throws Exception {
        try (ScriptedServer server = new ScriptedServer(conn -> {
            conn.send("SSH-2.0-OpenSSH_9.6\r\n".getBytes(StandardCharsets.US_ASCII));
            conn.clientClosed();
        })) {
            PlayerProtocolException e = assertThrows(PlayerProtocolException.class,
                    () -> PlayerClient.connect(LOCAL, server.port(), new PlayerClientOptions(300, 300, 1024, 16),
                            new PlayerCounters()));
            assertTrue(e.getMessage().contains("SSH-2.0-OpenSSH_9.6"), e.getMessage());
            server.await();
        }
    }

    @ParameterizedTest(name = "size field {0}")
    @CsvSource({"-1, negative", "2147483647, above the limit", "1048577, above the limit"})
    void badHeaderSizeIsRejectedBeforeAllocation(int size, String problem) throws Exception {
        XdrWriter w = new XdrWriter();
        new PlayerHeader(0, 0, Interfaces.LASER, 0, MessageType.DATA, 1, 1.0, 0, 0).encode(w);
        w.putInt(PlayerHeader.SIZE_FIELD_OFFSET, size);
        try (ScriptedServer server = new ScriptedServer(conn -> {
            conn.banner();
            conn.send(w.toByteArray());
            conn.clientClosed();
        })) {
            PlayerCounters counters = new PlayerCounters();
            try (PlayerClient client = PlayerClient.connect(LOCAL, server.port(), options(1000), counters)) {
                PlayerProtocolException e = assertThrows(PlayerProtocolException.class, () -> client.poll(2000, false));
                assertEquals("header.size", e.field());
                assertEquals(32 + 36, e.offset());
                assertTrue(e.getMessage().contains(problem), e.getMessage());
            }
            assertEquals(1, counters.snapshot().protocolErrors());
            server.await();
        }
    }

    @Test
    void connectionRefusedIsAConnectionError() throws Exception {
        int port;
        try (ServerSocket s = new ServerSocket(0, 1, java.net.InetAddress.getLoopbackAddress())) {
            port = s.getLocalPort();
        }
        int closedPort = port;
        PlayerConnectionException e = assertThrows(PlayerConnectionException.class,
                () -> PlayerClient.connect(LOCAL, closedPort, options(500), new PlayerCounters()));
        assertTrue(e.getMessage().contains("127.0.0.1:" + closedPort), e.getMessage());
    }

    @Test
    void rangerRangesBecomeScansWithTheConfiguredAnglesAndUnknownMessagesAreSkipped() throws Exception {
        byte[] s2c = Captures.bytes("push-with-ranger", "server-to-client.bin");
        JsonNode rangeMsg = Captures.messages("push-with-ranger", "s2c").stream()
                .filter(m -> m.get("summary").asText().contains("RANGER_DATA_RANGE")).findFirst().orElseThrow();
        RangerConfig config = new RangerConfig(-Math.toRadians(120), Math.toRadians(120), 0.017381, 0, 4, 0.01, 10);
        try (ScriptedServer server = new ScriptedServer(conn -> {
            conn.banner();
            XdrWriter w = new XdrWriter();
            byte[] req = conn.readMessage(); // DEV ranger:0
            int at = PlayerCodec.beginMessage(w, DeviceAddress.of(Interfaces.PLAYER, 0), MessageType.RESP_ACK,
                    Subtypes.PLAYER_REQ_DEV, 5.0);
            PlayerCodec.writeDeviceRequest(w, new io.rtaware.player.protocol.DeviceRequest(
                    DeviceAddress.of(Interfaces.RANGER, 0), Subtypes.ACCESS_OPEN, "stage"));
            PlayerCodec.endMessage(w, at);
            assertEquals(Subtypes.PLAYER_REQ_DEV, req[23]);
            conn.send(w.toByteArray());
            w.reset();
            conn.readMessage(); // GET_CONFIG
            at = PlayerCodec.beginMessage(w, DeviceAddress.of(Interfaces.RANGER, 0), MessageType.RESP_ACK,
                    Subtypes.RANGER_REQ_GET_CONFIG, 5.0);
            PlayerCodec.writeRangerConfig(w, config);
            PlayerCodec.endMessage(w, at);
            // an unknown interface (sonar) data message, then a ranger RANGE
            at = PlayerCodec.beginMessage(w, DeviceAddress.of(Interfaces.SONAR, 0), MessageType.DATA, 9, 5.0);
            w.writeInt(7);
            PlayerCodec.endMessage(w, at);
            conn.send(w.toByteArray());
            conn.send(s2c, rangeMsg.get("offset").asInt(), rangeMsg.get("length").asInt());
            conn.readMessage(); // simulation GET_POSE2D
            w.reset();
            at = PlayerCodec.beginMessage(w, DeviceAddress.of(Interfaces.SIMULATION, 0), MessageType.RESP_ACK,
                    Subtypes.SIMULATION_REQ_GET_POSE2D, 5.0);
            PlayerCodec.writeSimulationPose2d(w, new SimulationPose2d("r0", -3, -1.5, 0.25));
            PlayerCodec.endMessage(w, at);
            conn.send(w.toByteArray());
            conn.clientClosed();
        })) {
            PlayerCounters counters = new PlayerCounters();
            try (PlayerClient client = PlayerClient.connect(LOCAL, server.port(), options(2000), counters)) {
                client.subscribe(DeviceAddress.parse("ranger:0"));
                assertEquals(config, client.rangerConfig(0));
                client.poll(2000, false);
                while (client.rangerUpdates() == 0) {
                    client.poll(2000, false);
                }
                assertEquals(241, client.rangerScan().count());
                assertEquals(1.732051f, client.rangerScan().rangesM[0], 1e-6f);
                assertEquals(4.0, client.rangerScan().maxRangeM);
                assertEquals(Math.toRadians(1.0), client.rangerScan().angleIncrementRad(), 1e-9);
                assertEquals(1, counters.snapshot().skippedMessages());
                SimulationPose2d pose = client.simulationPose2d(0, "r0");
                assertEquals(new SimulationPose2d("r0", -3, -1.5, 0.25), pose);
            }
            server.await();
        }
    }

    @Test
    void requestsOfTheOtherInterfacesEncodeAsSpecified() throws Exception {
        try (ScriptedServer server = new ScriptedServer(conn -> {
            conn.banner();
            XdrWriter w = new XdrWriter();
            byte[] motor = conn.readMessage();
            XdrReader r = new XdrReader(motor, 0, motor.length);
            PlayerHeader h = PlayerHeader.decode(r);
            assertTrue(h.is(Interfaces.POSITION2D, 0, MessageType.REQ, Subtypes.POSITION2D_REQ_MOTOR_POWER));
            assertTrue(PlayerCodec.readMotorPower(r));
            PlayerCodec.endMessage(w, PlayerCodec.beginMessage(w, h.address(), MessageType.RESP_ACK, h.subtype(), 1));
            conn.send(w.toByteArray());
            byte[] laserCfg = conn.readMessage();
            assertEquals(40, laserCfg.length);
            w.reset();
            int at = PlayerCodec.beginMessage(w, DeviceAddress.of(Interfaces.LASER, 0), MessageType.RESP_ACK,
                    Subtypes.LASER_REQ_GET_CONFIG, 1);
            PlayerCodec.writeLaserConfig(w, new LaserConfig(-2f, 2f, 0.01f, 4f, 0.001f, 1, 10f));
            assertEquals(28, PlayerCodec.endMessage(w, at));
            conn.send(w.toByteArray());
            byte[] set = conn.readMessage();
            r = new XdrReader(set, 0, set.length);
            PlayerHeader.decode(r);
            assertEquals(new SimulationPose2d("r0", 1, 2, 3), PlayerCodec.readSimulationPose2d(r));
            assertEquals(40 + 4 + 4 + 4 + 24, set.length, "name_count, length, 'r0\\0' padded, pose");
            w.reset();
            PlayerCodec.endMessage(w, PlayerCodec.beginMessage(w, DeviceAddress.of(Interfaces.SIMULATION, 0),
                    MessageType.RESP_NACK, Subtypes.SIMULATION_REQ_SET_POSE2D, 1));
            conn.send(w.toByteArray());
            conn.clientClosed();
        })) {
            try (PlayerClient client = PlayerClient.connect(LOCAL, server.port(), options(2000), new PlayerCounters())) {
                client.setMotorPower(0, true);
                assertEquals(10f, client.laserConfig(0).scanningFrequencyHz());
                PlayerNackException e = assertThrows(PlayerNackException.class,
                        () -> client.setSimulationPose2d(0, new SimulationPose2d("r0", 1, 2, 3)));
                assertTrue(e.getMessage().contains("simulation:0"), e.getMessage());
            }
            server.await();
        }
    }

    @Test
    void rangerDataCodecRoundTrips() throws Exception {
        RangerData d = new RangerData(3);
        d.values[0] = 1;
        d.values[1] = 2;
        d.count = 2;
        XdrWriter w = new XdrWriter();
        PlayerCodec.writeRangerData(w, d);
        RangerData back = new RangerData(3);
        PlayerCodec.readRangerData(new XdrReader(w.array(), 0, w.size()), back);
        assertEquals(2, back.count);
        assertEquals(Banner.SIZE_BYTES, Banner.encode("3.1.1").length);
    }
}
