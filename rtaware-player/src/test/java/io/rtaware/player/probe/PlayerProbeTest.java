package io.rtaware.player.probe;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import io.rtaware.player.Captures;
import io.rtaware.player.ScriptedServer;
import io.rtaware.player.client.PlayerClientOptions;
import io.rtaware.player.protocol.MessageType;
import io.rtaware.player.protocol.Subtypes;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The probe against a scripted server and with bad addresses. */
@Timeout(30)
class PlayerProbeTest {

    @ParameterizedTest
    @ValueSource(strings = {"localhost", "127.0.0.1:", ":6665", "127.0.0.1:abc", "127.0.0.1:70000"})
    void badAddressGivesOneLine(String hostPort) {
        PlayerProbeException e = assertThrows(PlayerProbeException.class,
                () -> new PlayerProbe().run(hostPort, Duration.ZERO, System.out));
        assertFalse(e.getMessage().contains("\n"), e.getMessage());
        assertTrue(e.getMessage().contains(hostPort), e.getMessage());
    }

    @Test
    void unreachableServerGivesOneLine() throws Exception {
        int port;
        try (java.net.ServerSocket s = new java.net.ServerSocket(0, 1, java.net.InetAddress.getLoopbackAddress())) {
            port = s.getLocalPort();
        }
        String hostPort = "127.0.0.1:" + port;
        PlayerProbeException e = assertThrows(PlayerProbeException.class,
                () -> new PlayerProbe(new PlayerClientOptions(500, 500, 1 << 20, 4096))
                        .run(hostPort, Duration.ZERO, System.out));
        assertFalse(e.getMessage().contains("\n"), e.getMessage());
        assertTrue(e.getMessage().contains("cannot connect"), e.getMessage());
    }

    @Test
    void printsVersionDevicesAndData() throws Exception {
        byte[] s2c = Captures.bytes("push-with-ranger", "server-to-client.bin");
        List<JsonNode> msgs = Captures.messages("push-with-ranger", "s2c");
        JsonNode devlist = msgs.stream().filter(m -> m.get("summary").asText().endsWith("REQ_DEVLIST")).findFirst()
                .orElseThrow();
        JsonNode geom = msgs.stream().filter(m -> m.get("summary").asText().endsWith("GET_GEOM")).findFirst()
                .orElseThrow();
        List<JsonNode> data = msgs.stream().filter(m -> m.get("header").get("type").asInt() == MessageType.DATA)
                .limit(40).toList();
        try (ScriptedServer server = new ScriptedServer(conn -> {
            conn.banner();
            int subscriptions = 0;
            while (subscriptions < 2) {
                byte[] req = conn.readMessage();
                if (req[23] == Subtypes.PLAYER_REQ_DEVLIST && req[11] == 1) {
                    conn.send(s2c, devlist.get("offset").asInt(), devlist.get("length").asInt());
                } else if (req[11] == 4) {
                    conn.send(s2c, geom.get("offset").asInt(), geom.get("length").asInt());
                } else {
                    byte[] ack = req.clone();
                    ack[19] = MessageType.RESP_ACK;
                    conn.send(ack);
                    subscriptions += req[23] == Subtypes.PLAYER_REQ_DEV ? 1 : 0;
                }
            }
            for (JsonNode m : data) {
                conn.send(s2c, m.get("offset").asInt(), m.get("length").asInt());
            }
            conn.clientClosed();
        })) {
            ByteArrayOutputStream bytes = new ByteArrayOutputStream();
            int rc = new PlayerProbe().run("127.0.0.1:" + server.port(), Duration.ofMillis(300),
                    new PrintStream(bytes, true, StandardCharsets.UTF_8));
            server.await();
            String text = bytes.toString(StandardCharsets.UTF_8);
            assertEquals(0, rc, text);
            assertTrue(text.contains("version 3.1.1-dev"), text);
            assertTrue(text.contains("laser:0") && text.contains("position2d:0"), text);
            assertTrue(text.contains("241 beams"), text);
        }
    }
}
