package io.rtaware.player.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import io.rtaware.core.data.Input;
import io.rtaware.core.data.Key;
import io.rtaware.core.data.Output;
import io.rtaware.core.data.ReadStatus;
import io.rtaware.core.data.StateValue;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.time.Clock;
import io.rtaware.player.Captures;
import io.rtaware.player.ScriptedServer;
import io.rtaware.player.client.PlayerConnectionException;
import io.rtaware.player.protocol.MessageType;
import io.rtaware.player.protocol.PlayerCodec;
import io.rtaware.player.protocol.PlayerHeader;
import io.rtaware.player.protocol.VelocityCmd;
import io.rtaware.player.xdr.XdrReader;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.robot.msg.RobotKeys;
import io.rtaware.robot.msg.VelocityCommand;
import java.time.Duration;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** PlayerDataTask against a scripted server, with a hand-written TaskSetup double. */
@Timeout(30)
class PlayerDataTaskTest {

    /** Output double: one buffer, counts publishes. */
    static final class FakeOutput<T extends StateValue<T>> implements Output<T> {
        final Key<T> key;
        final T value;
        int published;

        FakeOutput(Key<T> key) {
            this.key = key;
            this.value = key.newBuffer();
        }

        @Override
        public Key<T> key() {
            return key;
        }

        @Override
        public T value() {
            return value;
        }

        @Override
        public void publish() {
            published++;
        }

        @Override
        public long commits() {
            return published;
        }
    }

    /** Input double: the test sets value and generation. */
    static final class FakeInput<T extends StateValue<T>> implements Input<T> {
        final Key<T> key;
        final T value;
        long generation;

        FakeInput(Key<T> key) {
            this.key = key;
            this.value = key.newBuffer();
        }

        @Override
        public Key<T> key() {
            return key;
        }

        @Override
        public T value() {
            return value;
        }

        @Override
        public ReadStatus status() {
            return generation == 0 ? ReadStatus.NONE : ReadStatus.NEW;
        }

        @Override
        public long ageNs() {
            return 0;
        }

        @Override
        public long generation() {
            return generation;
        }

        @Override
        public long maxAgeNs() {
            return Long.MAX_VALUE;
        }
    }

    /** TaskSetup double recording the declarations. */
    static final class FakeSetup implements TaskSetup {
        final Map<String, FakeOutput<?>> outputs = new HashMap<>();
        final Map<String, FakeInput<?>> inputs = new HashMap<>();

        @Override
        public String taskName() {
            return "player";
        }

        @Override
        public Schedule schedule() {
            return Schedule.continuous();
        }

        @Override
        public Clock clock() {
            return () -> 0L;
        }

        @Override
        public <T extends StateValue<T>> Input<T> consume(Key<T> key) {
            FakeInput<T> in = new FakeInput<>(key);
            inputs.put(key.name(), in);
            return in;
        }

        @Override
        public <T extends StateValue<T>> Input<T> consume(Key<T> key, Duration maxAge) {
            return consume(key);
        }

        @Override
        public <T extends StateValue<T>> Output<T> produce(Key<T> key) {
            FakeOutput<T> out = new FakeOutput<>(key);
            outputs.put(key.name(), out);
            return out;
        }
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
            FakeSetup setup = new FakeSetup();
            task.initialize(setup);
            assertEquals("3.1.1-dev", task.serverVersion());
            @SuppressWarnings("unchecked")
            FakeOutput<Odometry> odo = (FakeOutput<Odometry>) setup.outputs.get("odometry");
            @SuppressWarnings("unchecked")
            FakeOutput<LaserScan> laser = (FakeOutput<LaserScan>) setup.outputs.get("laser");
            @SuppressWarnings("unchecked")
            FakeInput<VelocityCommand> motor = (FakeInput<VelocityCommand>) setup.inputs.get("motor");
            long now = 0;
            for (int i = 0; i < 200 && (odo.published == 0 || laser.published == 0
                    || task.stats().odometryMessages() < 2 || task.stats().scanMessages() < 2); i++) {
                task.execute(now);
            }
            assertTrue(odo.published >= 1 && laser.published >= 1);
            assertTrue(odo.published <= 2 && laser.published <= 2, "published only when new data arrived");
            int odoPublished = odo.published;
            task.execute(now); // nothing new arrives
            assertEquals(odoPublished, odo.published);
            assertEquals(-3.0, odo.value.xM, 0.1);
            assertEquals(241, laser.value.count());
            assertEquals(4.0, laser.value.maxRangeM);
            assertEquals(0, commands.size());

            motor.value.set(0.3, 0.1);
            motor.generation = 1;
            task.execute(1_000_000_000L); // new generation, changed: sent
            motor.generation = 2;
            task.execute(1_100_000_000L); // new generation, same value: not sent
            task.execute(1_600_000_000L); // keep-alive: 500 ms after the last send
            task.execute(1_700_000_000L); // nothing
            task.terminate();
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
            task.initialize(new FakeSetup());
            server.await();
            PlayerConnectionException e = assertThrows(PlayerConnectionException.class, () -> {
                for (int i = 0; i < 100; i++) {
                    task.execute(0);
                }
            });
            assertTrue(e.getMessage().contains("closed the connection"), e.getMessage());
            assertEquals(1, task.stats().connectionLosses());
            PlayerConnectionException again = assertThrows(PlayerConnectionException.class, () -> task.execute(0));
            assertTrue(again.getMessage().contains("reconnection disabled"), again.getMessage());
            task.terminate();
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
        task.initialize(new FakeSetup()); // unreachable: counted, retried later
        assertEquals(1, task.stats().connectionLosses());
        PlayerConnectionException first = assertThrows(PlayerConnectionException.class, () -> task.execute(0));
        assertTrue(first.getMessage().contains("attempt 1") && first.getMessage().contains("next in 100 ms"),
                first.getMessage());
        task.execute(50_000_000L); // before the back-off ends: waits, no attempt
        assertEquals(2, task.stats().connectionLosses());
        PlayerConnectionException second = assertThrows(PlayerConnectionException.class,
                () -> task.execute(100_000_000L));
        assertTrue(second.getMessage().contains("attempt 2") && second.getMessage().contains("next in 200 ms"),
                second.getMessage());
        assertThrows(IllegalArgumentException.class, () -> PlayerConfig.of("", 0));
        task.terminate();
    }
}
