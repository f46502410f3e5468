package io.rtaware.foxglove;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import com.fasterxml.jackson.databind.JsonNode;
import io.rtaware.core.testing.Waits;
import io.rtaware.record.TapChannel;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.net.Socket;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * The server end to end over loopback, with the JDK's WebSocket client: what a client gets on
 * connecting, subscriptions, Message Data frames on exact bytes, latched channels, the bounds on
 * clients and on each client's send buffer, and the address it listens on.
 */
class FoxgloveServerTest {

    private static final TapChannel SCAN = new TapChannel(1, "/scan", "sensor_msgs/msg/LaserScan",
            "float32 angle_min\n", false);
    private static final TapChannel TIMING = new TapChannel(2, "/rtaware/timing/avoid", "rtaware_msgs/msg/TaskCycle",
            "int64 release_ns\n", false);
    private static final TapChannel MAP = new TapChannel(3, "/map", "nav_msgs/msg/OccupancyGrid", "int8[] data\n",
            true);

    private final List<FoxgloveServer> servers = new ArrayList<>();
    private final List<WsClient> clients = new ArrayList<>();

    @AfterEach
    void closeAll() {
        clients.forEach(WsClient::close);
        servers.forEach(FoxgloveServer::close);
    }

    private FoxgloveServer server(int maxClients, int sendBufferBytes) {
        FoxgloveServer s = FoxgloveServer.start(FoxgloveAddress.parse("0"), "rtaware test", Map.of("ROS_DISTRO", "jazzy"),
                maxClients, sendBufferBytes);
        servers.add(s);
        s.channel(SCAN);
        s.channel(TIMING);
        s.channel(MAP);
        return s;
    }

    private WsClient client(FoxgloveServer server) throws Exception {
        WsClient c = WsClient.connect(server.url());
        clients.add(c);
        return c;
    }

    /** Connects and takes the Server Info and the Advertise every client gets first. */
    private WsClient connected(FoxgloveServer server) throws Exception {
        WsClient c = client(server);
        assertEquals("serverInfo", c.nextJson().path("op").asText());
        assertEquals("advertise", c.nextJson().path("op").asText());
        return c;
    }

    /**
     * Sends an op the server does not support and waits for its status reply: the server reads a
     * connection's messages in order, so everything sent before has been handled, and anything
     * it sent before the reply has arrived before it.
     */
    private static void barrier(WsClient c) throws Exception {
        c.send("{\"op\":\"getParameters\",\"parameterNames\":[]}");
        JsonNode status = c.nextJson();
        assertEquals("status", status.path("op").asText(), "the barrier's reply: " + status);
        assertTrue(status.path("message").asText().contains("'getParameters' is not supported"), status.toString());
    }

    private static byte[] frame(int subscriptionId, long timeNs, byte[] payload) {
        ByteBuffer b = ByteBuffer.allocate(13 + payload.length).order(ByteOrder.LITTLE_ENDIAN);
        b.put((byte) 1).putInt(subscriptionId).putLong(timeNs).put(payload);
        return b.array();
    }

    @Test
    void aClientGetsServerInfoThenEveryChannelWithItsRos2Schema() throws Exception {
        FoxgloveServer server = server(4, 1 << 20);
        WsClient c = client(server);
        assertEquals(FoxgloveProtocol.SUBPROTOCOL, c.socket().getSubprotocol(), "the subprotocol is selected");
        JsonNode info = c.nextJson();
        assertEquals("serverInfo", info.path("op").asText(), info.toString());
        assertEquals("rtaware test", info.path("name").asText());
        assertEquals("[\"time\"]", info.path("capabilities").toString(), "the time capability only: " + info);
        assertEquals("jazzy", info.path("metadata").path("ROS_DISTRO").asText());
        JsonNode advertise = c.nextJson();
        assertEquals("advertise", advertise.path("op").asText(), advertise.toString());
        assertEquals(3, advertise.path("channels").size(), advertise.toString());
        JsonNode scan = advertise.path("channels").get(0);
        assertEquals(1, scan.path("id").asInt());
        assertEquals("/scan", scan.path("topic").asText());
        assertEquals("cdr", scan.path("encoding").asText());
        assertEquals("sensor_msgs/msg/LaserScan", scan.path("schemaName").asText());
        assertEquals("float32 angle_min\n", scan.path("schema").asText());
        assertEquals("ros2msg", scan.path("schemaEncoding").asText());
        assertEquals(1, server.clients(), "one client connected");
        assertEquals(1, server.stats().clientsAccepted());
    }

    /** foxglove_bridge 3.x's clients offer foxglove.sdk.v1 (some only it); older ones foxglove.websocket.v1. */
    @Test
    void theSdkSubprotocolIsSelectedWheneverOfferedAndTheOlderOneOtherwise() throws Exception {
        FoxgloveServer server = server(4, 1 << 20);
        WsClient sdkOnly = WsClient.connect(server.url(), FoxgloveProtocol.SUBPROTOCOL_SDK);
        clients.add(sdkOnly);
        assertEquals(FoxgloveProtocol.SUBPROTOCOL_SDK, sdkOnly.socket().getSubprotocol());
        assertEquals("serverInfo", sdkOnly.nextJson().path("op").asText());
        WsClient olderFirst = WsClient.connect(server.url(), FoxgloveProtocol.SUBPROTOCOL, FoxgloveProtocol.SUBPROTOCOL_SDK);
        clients.add(olderFirst);
        assertEquals(FoxgloveProtocol.SUBPROTOCOL_SDK, olderFirst.socket().getSubprotocol(), "preferred when offered");
        WsClient older = client(server);
        assertEquals(FoxgloveProtocol.SUBPROTOCOL, older.socket().getSubprotocol());
    }

    /** With the time capability every client's timeline follows the run's log time. */
    @Test
    void everyClientGetsTheRunsTimeAsItMovesOn() throws Exception {
        FoxgloveServer server = server(4, 1 << 20);
        WsClient c = connected(server); // subscribed to nothing: the time is for every client
        long t0 = 1_700_000_000_000_000_000L;
        server.message(1, t0, new byte[] {1}, 0, 1);
        assertEquals(t0, c.nextTime(), "the first message's log time");
        server.message(2, t0 + 10_000_000L, new byte[] {1}, 0, 1); // 10 ms later: within the step
        server.message(1, t0 + FoxgloveServer.TIME_STEP_MS * 1_000_000L, new byte[] {1}, 0, 1);
        assertEquals(t0 + FoxgloveServer.TIME_STEP_MS * 1_000_000L, c.nextTime(), "one step of log time later");
        server.message(1, t0 + 20_000_000L, new byte[] {1}, 0, 1); // an earlier log time: never back
        barrier(c);
        assertEquals(0, c.queuedTimes(), "one Time frame a step, never backwards");
        assertEquals(0, c.queued(), "no message data: nothing subscribed");
    }

    /** What a program's own main gets from {@code start(address, name)}: the command line's server. */
    @Test
    void theShortStartServesAsTheCommandLineDoes() throws Exception {
        FoxgloveServer server = FoxgloveServer.start(FoxgloveAddress.parse("0"), "my controller");
        servers.add(server);
        JsonNode info = client(server).nextJson();
        assertEquals("my controller", info.path("name").asText(), info.toString());
        assertEquals(TapChannel.ROS_DISTRO, info.path("metadata").path("ROS_DISTRO").asText(),
                "the ROS 2 distribution the recordings' types follow: " + info);
        assertEquals(FoxgloveServer.DEFAULT_MAX_CLIENTS, server.stats().maxClients(), "the default bound on clients");
        assertEquals(FoxgloveServer.DEFAULT_SEND_BUFFER_BYTES, server.stats().sendBufferBytes(),
                "the default send buffer of a client");
        assertEquals("127.0.0.1", server.address().getAddress().getHostAddress(), "loopback unless told otherwise");
    }

    @Test
    void aChannelDeclaredLaterIsAdvertisedToConnectedClients() throws Exception {
        FoxgloveServer server = server(4, 1 << 20);
        WsClient c = connected(server);
        server.channel(new TapChannel(4, "/rtaware/events", "rtaware_msgs/msg/MonitorEvent", "string kind\n", false));
        JsonNode advertise = c.nextJson();
        assertEquals("advertise", advertise.path("op").asText(), advertise.toString());
        assertEquals(1, advertise.path("channels").size());
        assertEquals("/rtaware/events", advertise.path("channels").get(0).path("topic").asText());
    }

    @Test
    void aSubscriberGetsEachMessageAsAMessageDataFrameStampedWithItsLogTime() throws Exception {
        FoxgloveServer server = server(4, 1 << 20);
        WsClient c = connected(server);
        c.send("{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":7,\"channelId\":1},{\"id\":4294967295,\"channelId\":2}]}");
        barrier(c);
        byte[] payload = {0, 1, 0, 0, 42, 43, 44};
        server.message(1, 1_700_000_000_123_456_789L, new byte[] {9, 9, 0, 1, 0, 0, 42, 43, 44, 9}, 2, 7);
        assertArrayEquals(frame(7, 1_700_000_000_123_456_789L, payload), c.nextBinary(),
                "opcode 1, subscription 7, the log time, the CDR bytes");
        server.message(2, 5L, new byte[] {1, 2}, 0, 2);
        assertArrayEquals(frame(-1, 5L, new byte[] {1, 2}), c.nextBinary(), "subscription id 4294967295");
        FoxgloveStats stats = server.stats();
        assertEquals(2, stats.messagesSent());
        assertEquals(13 + 7 + 13 + 2, stats.bytesSent());
        assertEquals(0, stats.messagesDropped());
    }

    @Test
    void onlySubscribedChannelsAreSentAndUnsubscribeEndsThem() throws Exception {
        FoxgloveServer server = server(4, 1 << 20);
        WsClient c = connected(server);
        c.send("{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":0,\"channelId\":1}]}");
        barrier(c);
        server.message(2, 1, new byte[] {1}, 0, 1); // not subscribed
        server.message(1, 2, new byte[] {2}, 0, 1);
        assertArrayEquals(frame(0, 2, new byte[] {2}), c.nextBinary(), "the subscribed channel's message only");
        c.send("{\"op\":\"unsubscribe\",\"subscriptionIds\":[0]}");
        barrier(c);
        server.message(1, 3, new byte[] {3}, 0, 1);
        barrier(c); // a frame sent after the unsubscribe would arrive before this reply
        assertEquals(0, c.queued(), "nothing after the unsubscribe");
        assertEquals(1, server.stats().messagesSent());
    }

    @Test
    void aLateSubscriberToALatchedChannelGetsItsLastMessage() throws Exception {
        FoxgloveServer server = server(4, 1 << 20);
        server.message(3, 100, new byte[] {1, 1}, 0, 2);
        server.message(3, 200, new byte[] {2, 2, 2}, 0, 3);
        server.message(1, 300, new byte[] {3}, 0, 1); // not latched: gone for later subscribers
        WsClient c = connected(server);
        c.send("{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":5,\"channelId\":3},{\"id\":6,\"channelId\":1}]}");
        assertArrayEquals(frame(5, 200, new byte[] {2, 2, 2}), c.nextBinary(), "the last /map, once");
        barrier(c);
        assertEquals(0, c.queued(), "nothing else");
        server.message(3, 400, new byte[] {4}, 0, 1);
        assertArrayEquals(frame(5, 400, new byte[] {4}), c.nextBinary(), "then every new one");
    }

    @Test
    void badRequestsGetAStatusAndTheConnectionGoesOn() throws Exception {
        FoxgloveServer server = server(4, 1 << 20);
        WsClient c = connected(server);
        c.send("{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":1,\"channelId\":99}]}");
        JsonNode unknown = c.nextJson();
        assertEquals(FoxgloveProtocol.STATUS_WARNING, unknown.path("level").asInt(), unknown.toString());
        assertTrue(unknown.path("message").asText().contains("no channel 99"), unknown.toString());
        c.send("{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":1,\"channelId\":1}]}");
        c.send("{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":1,\"channelId\":2}]}");
        JsonNode reused = c.nextJson();
        assertEquals(FoxgloveProtocol.STATUS_ERROR, reused.path("level").asInt(), reused.toString());
        assertTrue(reused.path("message").asText().contains("subscription id 1 is in use"), reused.toString());
        c.send("{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":2,\"channelId\":1}]}");
        JsonNode twice = c.nextJson();
        assertTrue(twice.path("message").asText().contains("is subscribed already"), twice.toString());
        c.send("not json");
        JsonNode malformed = c.nextJson();
        assertEquals(FoxgloveProtocol.STATUS_ERROR, malformed.path("level").asInt(), malformed.toString());
        assertTrue(malformed.path("message").asText().startsWith("rtaware: not JSON"), malformed.toString());
        c.socket().sendBinary(ByteBuffer.wrap(new byte[] {1, 0, 0, 0, 0}), true).get(20, TimeUnit.SECONDS);
        JsonNode binary = c.nextJson();
        assertTrue(binary.path("message").asText().contains("binary client messages are not supported"),
                binary.toString());
        server.message(1, 9, new byte[] {9}, 0, 1);
        assertArrayEquals(frame(1, 9, new byte[] {9}), c.nextBinary(), "the first subscription still works");
    }

    @Test
    void clientsBeyondTheLimitAreRefusedAfterTheirHandshakeAndCounted() throws Exception {
        FoxgloveServer server = server(1, 1 << 20);
        connected(server);
        WsClient second = client(server);
        assertEquals(1013, second.awaitCloseCode(), "WebSocket close 1013, try again later");
        assertEquals(1, server.stats().clientsRefused(), server.stats().toString());
        assertEquals(1, server.stats().clientsAccepted());
        assertEquals(1, server.clients());
    }

    /**
     * The third red team's lock-out: idle TCP connections (no byte sent, or a trickle) used to
     * take the client slots when they connected. Now a slot is taken by a finished handshake, and
     * more idle connections than may wait close the oldest of them.
     */
    @Test
    void idleConnectionsCannotLockClientsOut() throws Exception {
        FoxgloveServer server = server(2, 1 << 20);
        int idle = FoxgloveServer.MAX_PENDING_HANDSHAKES + 8;
        List<Socket> sockets = new ArrayList<>();
        try {
            for (int i = 0; i < idle; i++) {
                Socket s = new Socket(server.address().getAddress(), server.address().getPort());
                if (i % 2 == 1) {
                    s.getOutputStream().write("GET / HTTP/1.1\r\n".getBytes(StandardCharsets.US_ASCII)); // a trickle
                }
                sockets.add(s);
            }
            connected(server);
            connected(server);
            FoxgloveStats stats = server.stats();
            assertEquals(2, stats.clientsAccepted(), stats.toString());
            assertEquals(0, stats.clientsRefused(), stats.toString());
            assertTrue(stats.connectionsClosedInHandshake() >= idle - FoxgloveServer.MAX_PENDING_HANDSHAKES,
                    "the oldest idle connections were closed to make room: " + stats);
            sockets.get(0).setSoTimeout(20_000);
            assertEquals(-1, sockets.get(0).getInputStream().read(), "the oldest idle connection was closed");
        } finally {
            for (Socket s : sockets) {
                s.close();
            }
        }
    }

    /**
     * The third red team's crash: a client that never reads, sending subscribe requests that
     * name 1 600 unknown channels each, got a status per unknown channel written without a
     * bound until the heap was full. Now each request gets one status naming the first ids, and
     * what waits for that client stays under its send buffer.
     */
    @Test
    void aClientThatNeverReadsCannotMakeTheServerHoldMoreThanItsSendBuffer() throws Exception {
        int bufferBytes = 64 << 10;
        FoxgloveServer server = server(2, bufferBytes);
        StringBuilder request = new StringBuilder("{\"op\":\"subscribe\",\"subscriptions\":[");
        for (int i = 0; i < 1600; i++) {
            request.append(i == 0 ? "" : ",").append("{\"id\":").append(i).append(",\"channelId\":").append(100_000 + i)
                    .append('}');
        }
        byte[] frame = RawWebSocket.textFrame(request.append("]}").toString());
        int frames = 300; // 17 MB of requests; 480 000 statuses (about 36 MB) before the fix
        try (RawWebSocket hostile = RawWebSocket.connect(server.address(), 4096)) {
            for (int i = 0; i < frames; i++) {
                hostile.write(frame);
            }
            Waits.until(() -> server.requestsHandled() == frames || server.stats().statusesDropped() > 0,
                    Duration.ofSeconds(30), "the server read the requests");
            assertTrue(server.mostBytesWaiting() <= bufferBytes,
                    server.mostBytesWaiting() + " bytes wait for one client, more than its " + bufferBytes);
            WsClient other = connected(server);
            barrier(other);
        }
    }

    @Test
    void aRequestNamingManyUnknownChannelsGetsOneStatus() throws Exception {
        FoxgloveServer server = server(2, 1 << 20);
        WsClient c = connected(server);
        c.send("{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":1,\"channelId\":90},{\"id\":2,\"channelId\":1},"
                + "{\"id\":3,\"channelId\":91}]}");
        JsonNode status = c.nextJson();
        assertEquals("rtaware: no channel 90, 91", status.path("message").asText(), status.toString());
        StringBuilder many = new StringBuilder("{\"op\":\"unsubscribe\",\"subscriptionIds\":[");
        for (int i = 0; i < 25; i++) {
            many.append(i == 0 ? "" : ",").append(100 + i);
        }
        c.send(many.append("]}").toString());
        assertEquals("rtaware: no subscription 100, 101, 102, 103, 104, 105, 106, 107, 108, 109 and 15 more (25 ids)",
                c.nextJson().path("message").asText());
        barrier(c);
        assertEquals(0, c.queued(), "one status a request");
    }

    /** An advertisement a client cannot take (it does not read) closes that client, counted. */
    @Test
    void aClientWithNoRoomForAnAdvertisementIsClosed() throws Exception {
        int bufferBytes = 64 << 10;
        FoxgloveServer server = server(2, bufferBytes);
        WsClient slow = connected(server);
        slow.pause();
        String schema = "float32 x\n".repeat(4096); // 40 KB a channel
        int id = 10;
        while (server.stats().clientsClosedSlow() == 0 && id < 2_000) { // at most 80 MB
            server.channel(new TapChannel(id++, "/t" + id, "std_msgs/msg/Float32", schema, false));
            assertTrue(server.mostBytesWaiting() <= bufferBytes + schema.length() + 1024,
                    server.mostBytesWaiting() + " bytes wait for the slow client");
        }
        assertEquals(1, server.stats().clientsClosedSlow(), server.stats().toString());
        Waits.until(() -> server.clients() == 0, Duration.ofSeconds(30), "the slow client is gone");
    }

    @Test
    void everyAddressIsSaidToBeExposed() {
        FoxgloveServer every = FoxgloveServer.start(FoxgloveAddress.parse("0.0.0.0:0"), "t", Map.of(), 1, 1 << 20);
        servers.add(every);
        assertTrue(every.exposed());
        assertTrue(every.listening().equals("0.0.0.0:" + every.address().getPort())
                || every.listening().equals("[::]:" + every.address().getPort()), every.listening());
        FoxgloveServer loopback = server(1, 1 << 20);
        assertTrue(!loopback.exposed());
        assertEquals("127.0.0.1:" + loopback.address().getPort(), loopback.listening());
    }

    @Test
    void aSlowClientLosesMessagesCountedWhileTheWriterNeverWaits() throws Exception {
        int bufferBytes = 64 << 10;
        FoxgloveServer server = server(4, bufferBytes);
        WsClient slow = connected(server);
        WsClient fast = connected(server);
        slow.send("{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":1,\"channelId\":1}]}");
        fast.send("{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":1,\"channelId\":2}]}");
        barrier(slow);
        barrier(fast);
        slow.pause();
        byte[] scan = new byte[16 << 10];
        int offered = 4096; // 64 MiB: far more than the socket buffers and the 64 KiB send buffer together
        int small = 256; // 256 frames of 14 bytes: always room in the other client's buffer
        for (int i = 0; i < offered; i++) {
            Arrays.fill(scan, 0, 8, (byte) i);
            server.message(1, i, scan, 0, scan.length);
            if (i < small) {
                server.message(2, i, new byte[] {(byte) i}, 0, 1);
            }
        }
        FoxgloveStats stats = server.stats();
        assertTrue(stats.messagesDropped() > 0, "the slow client lost messages: " + stats);
        assertEquals(offered + small, stats.messagesSent() + stats.messagesDropped(),
                "each one sent or counted: " + stats);
        for (int i = 0; i < small; i++) {
            assertArrayEquals(frame(1, i, new byte[] {(byte) i}), fast.nextBinary(),
                    "the other client got every message of its channel, in order: " + i);
        }
        long slowSent = stats.messagesSent() - small;
        slow.resume();
        long previous = -1;
        for (long k = 0; k < slowSent; k++) {
            byte[] b = slow.nextBinary();
            long time = ByteBuffer.wrap(b, 5, 8).order(ByteOrder.LITTLE_ENDIAN).getLong();
            assertTrue(time > previous, "what the slow client got is in order: " + time + " after " + previous);
            previous = time;
        }
        barrier(slow);
        assertEquals(0, slow.queued(), "exactly what was counted as sent");
    }

    @Test
    void aMessageNoClientSubscribedToAllocatesNothingOnTheWritersThread() throws Exception {
        com.sun.management.ThreadMXBean threads =
                (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        assumeTrue(threads.isThreadAllocatedMemorySupported(), "thread allocation counting unsupported");
        FoxgloveServer server = server(4, 1 << 20);
        WsClient c = connected(server); // connected, subscribed to nothing
        byte[] data = new byte[512];
        long id = Thread.currentThread().getId();
        long allocated = Long.MAX_VALUE;
        // Until the JIT has compiled the hand-over (escape analysis removes its boxing), the
        // interpreter allocates; a loaded machine compiles later, so warm up for up to 50 rounds.
        for (int round = 0; round < 50 && allocated != 0; round++) {
            long before = threads.getThreadAllocatedBytes(id);
            for (int i = 0; i < 20_000; i++) {
                server.message(1, i, data, 0, data.length);
                server.message(3, i, data, 0, data.length); // latched: kept, in a buffer of its own
                server.message(99, i, data, 0, data.length); // no such channel
            }
            allocated = Math.min(allocated, threads.getThreadAllocatedBytes(id) - before);
        }
        assertEquals(0, allocated, "bytes allocated handing over 60 000 messages nobody subscribed to");
        barrier(c);
        assertEquals(0, c.queued(), "nothing sent");
        assertEquals(0, server.stats().messagesSent() + server.stats().messagesDropped(), server.stats().toString());
    }

    @Test
    void aBarePortListensOnLoopbackOnly() {
        FoxgloveServer server = server(1, 1 << 20);
        assertTrue(server.address().getAddress().isLoopbackAddress(), "bound to " + server.address());
        assertTrue(server.url().startsWith("ws://127.0.0.1:"), server.url());
        assertTrue(server.address().getPort() > 0, "a free port was taken");
    }

    @Test
    void aTakenPortIsOneLineNamingTheAddress() {
        FoxgloveServer first = server(1, 1 << 20);
        int port = first.address().getPort();
        FoxgloveAddressException e = assertThrows(FoxgloveAddressException.class, () -> FoxgloveServer.start(
                new FoxgloveAddress("127.0.0.1", port), "second", Map.of(), 1, 1 << 20));
        assertEquals(1, e.getMessage().lines().count(), e.getMessage());
        assertTrue(e.getMessage().startsWith("cannot serve Foxglove on 127.0.0.1:" + port + ": "), e.getMessage());
    }

    @Test
    void anUnknownHostIsOneLine() {
        FoxgloveAddressException e = assertThrows(FoxgloveAddressException.class, () -> FoxgloveServer.start(
                new FoxgloveAddress("no-such-host.invalid", 0), "x", Map.of(), 1, 1 << 20));
        assertTrue(e.getMessage().contains("cannot resolve 'no-such-host.invalid'"), e.getMessage());
    }

    @Test
    void closingEndsEveryConnectionWithGoingAway() throws Exception {
        FoxgloveServer server = server(4, 1 << 20);
        WsClient c = connected(server);
        server.close();
        assertEquals(1001, c.awaitCloseCode(), "WebSocket close 1001, going away");
    }
}
