package io.rtaware.player.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import io.rtaware.core.testing.TaskHarness;
import io.rtaware.player.Captures;
import io.rtaware.player.ScriptedServer;
import io.rtaware.player.client.PlayerConnectionException;
import io.rtaware.player.protocol.MessageType;
import io.rtaware.player.protocol.PlayerCodec;
import io.rtaware.player.protocol.PlayerHeader;
import io.rtaware.player.protocol.VelocityCmd;
import io.rtaware.player.xdr.XdrReader;
import io.rtaware.robot.msg.RobotKeys;
import io.rtaware.robot.msg.VelocityCommand;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * PlayerDataTask against a scripted server, driven through the real monitor's handles by the
 * core's {@link TaskHarness} (the motor command is a scripted input).
 */
@Timeout(30)
class PlayerDataTaskTest {

    private static TaskHarness harness(PlayerDataTask task) {
        return TaskHarness.builder().input(RobotKeys.MOTOR).task("player", task).build();
    }

    private static VelocityCommand motor(double vx, double omega) {
        VelocityCommand command = new VelocityCommand();
        command.set(vx, omega);
        return command;
    }

    private static byte[] ack(byte[] request) {
        byte[] reply = request.clone();
        reply[19] = MessageType.RESP_ACK;
        return reply;
    }

    private static PlayerHeader header(byte[] msg) throws Exception {
        return PlayerHeader.decode(new XdrReader(msg, 0, msg.length));
    }

    @Test
    void publishesDataSendsCommandsOnChangeKeepsAliveAndStopsOnTerminate() throws Exception {
        byte[] s2c = Captures.bytes("push-with-ranger", "server-to-client.bin");
        List<JsonNode> data = Captures.messages("push-with-ranger", "s2c").stream()
                .filter(m -> m.get("header").get("type").asInt() == MessageType.DATA).toList();
        List<String> received = new CopyOnWriteArrayList<>();
        List<VelocityCmd> commands = new CopyOnWriteArrayList<>();
        try (ScriptedServer server = new ScriptedServer(conn -> {
            conn.banner();
            for (int i = 0; i < 4; i++) { // DATAMODE, ADD_REPLACE_RULE, DEV position2d, DEV laser
                byte[] req = conn.readMessage();
                received.add(header(req).toString());
                conn.send(ack(req));
            }
            for (JsonNode m : data.subList(0, 8)) {
                conn.send(s2c, m.get("offset").asInt(), m.get("length").asInt());
            }
            while (true) {
                byte[] msg = conn.readMessage();
                PlayerHeader h = header(msg);
                received.add(h.toString());
                if (h.type() == MessageType.CMD) {
                    XdrReader r = new XdrReader(msg, 40, msg.length - 40);
                    commands.add(PlayerCodec.readVelocityCmd(r));
                } else {
                    conn.send(ack(msg));
                    if (received.stream().filter(s -> s.startsWith("REQ player")).count() == 6) {
                        break;
                    }
                }
            }
            if (!conn.clientClosed()) {
                throw new AssertionError("client did not close");
            }
        })) {
            PlayerDataTask task = new PlayerDataTask(PlayerConfig.of("127.0.0.1", server.port()));
            TaskHarness h = harness(task);
            assertEquals("3.1.1-dev", task.serverVersion());
            long now = 0;
            for (int i = 0; i < 200 && (h.generation(RobotKeys.ODOMETRY) == 0 || h.generation(RobotKeys.LASER) == 0
                    || task.stats().odometryMessages() < 2 || task.stats().scanMessages() < 2); i++) {
                assertNull(h.cycle("player", now));
            }
            long odoCommits = h.generation(RobotKeys.ODOMETRY);
            long laserCommits = h.generation(RobotKeys.LASER);
            assertTrue(odoCommits >= 1 && laserCommits >= 1);
            assertTrue(odoCommits <= 2 && laserCommits <= 2, "committed only when new data arrived");
            assertNull(h.cycle("player", now)); // nothing new arrives
            assertEquals(odoCommits, h.generation(RobotKeys.ODOMETRY));
            assertEquals(-3.0, h.read(RobotKeys.ODOMETRY).xM, 0.1);
            assertEquals(241, h.read(RobotKeys.LASER).count());
            assertEquals(4.0, h.read(RobotKeys.LASER).maxRangeM);
            assertEquals(0, commands.size());

            h.publish(RobotKeys.MOTOR, motor(0.3, 0.1), 1_000_000_000L);
            h.cycle("player", 1_000_000_000L); // new generation, changed: sent
            h.publish(RobotKeys.MOTOR, motor(0.3, 0.1), 1_100_000_000L);
            h.cycle("player", 1_100_000_000L); // new generation, same value: not sent
            h.cycle("player", 1_600_000_000L); // keep-alive: 500 ms after the last send
            h.cycle("player", 1_700_000_000L); // nothing
            h.stop(); // terminate(): zero velocity, unsubscribe, close
            server.await();
            assertEquals(List.of(new VelocityCmd(0.3, 0, 0.1, 1), new VelocityCmd(0.3, 0, 0.1, 1),
                    new VelocityCmd(0, 0, 0, 1)), commands);
            int stop = received.indexOf(received.stream().filter(s -> s.startsWith("CMD")).reduce((a, b) -> b)
                    .orElseThrow());
            assertTrue(received.get(stop + 1).startsWith("REQ player") && received.get(stop + 2).startsWith("REQ player"),
                    "zero velocity before the unsubscriptions: " + received);
            assertEquals(3, task.stats().commandsSent());
            assertEquals(0, task.stats().protocolErrors());
        }
    }

    @Test
    void connectionLossIsThrownFromExecuteAndCounted() throws Exception {
        try (ScriptedServer server = new ScriptedServer(conn -> {
            conn.banner();
            for (int i = 0; i < 4; i++) {
                conn.send(ack(conn.readMessage()));
            }
            conn.close();
        })) {
            PlayerDataTask task = new PlayerDataTask(PlayerConfig.of("127.0.0.1", server.port()));
            TaskHarness h = harness(task);
            server.await();
            Throwable lost = null;
            for (int i = 0; i < 100 && lost == null; i++) {
                lost = h.cycle("player", 0);
            }
            PlayerConnectionException e = assertInstanceOf(PlayerConnectionException.class, lost);
            assertTrue(e.getMessage().contains("closed the connection"), e.getMessage());
            assertEquals(1, task.stats().connectionLosses());
            PlayerConnectionException again = assertInstanceOf(PlayerConnectionException.class, h.cycle("player", 0));
            assertTrue(again.getMessage().contains("reconnection disabled"), again.getMessage());
            assertEquals(0, h.generation(RobotKeys.ODOMETRY), "a cycle that threw committed nothing");
            h.stop();
        }
    }

    @Test
    void reconnectsWithBackoffAfterALoss() throws Exception {
        int port;
        try (java.net.ServerSocket s = new java.net.ServerSocket(0, 1, java.net.InetAddress.getLoopbackAddress())) {
            port = s.getLocalPort();
        }
        PlayerConfig config = PlayerConfig.of("127.0.0.1", port).withReconnect(true, 100, 400)
                .withTimeouts(300, 300, 1000);
        PlayerDataTask task = new PlayerDataTask(config);
        TaskHarness h = harness(task); // initialize: unreachable, counted, retried later
        assertEquals(1, task.stats().connectionLosses());
        PlayerConnectionException first = assertInstanceOf(PlayerConnectionException.class, h.cycle("player", 0));
        assertTrue(first.getMessage().contains("attempt 1") && first.getMessage().contains("next in 100 ms"),
                first.getMessage());
        assertNull(h.cycle("player", 50_000_000L)); // before the back-off ends: waits, no attempt
        assertEquals(2, task.stats().connectionLosses());
        PlayerConnectionException second = assertInstanceOf(PlayerConnectionException.class,
                h.cycle("player", 100_000_000L));
        assertTrue(second.getMessage().contains("attempt 2") && second.getMessage().contains("next in 200 ms"),
                second.getMessage());
        assertThrows(IllegalArgumentException.class, () -> PlayerConfig.of("", 0));
        h.stop();
    }
}
