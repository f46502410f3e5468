package io.rtaware.sim.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.testing.Waits;
import io.rtaware.core.time.SystemClock;
import io.rtaware.player.protocol.Interfaces;
import io.rtaware.player.protocol.MessageType;
import io.rtaware.player.protocol.PlayerCodec;
import io.rtaware.player.protocol.ReplaceRule;
import io.rtaware.player.protocol.Subtypes;
import java.io.IOException;
import java.io.InputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** The server survives its clients and its machine: failing accepts, thread limits, greedy or stalled clients. */
class ServerLimitsTest {

    private static final long MS = 1_000_000L;

    private PlayerSimServer server;

    @AfterEach
    void stop() {
        if (server != null) {
            server.close();
        }
    }

    private static ServerEnvironment env(ServerEnvironment.Accept accept, java.util.concurrent.ThreadFactory threads,
                                         ServerEnvironment.Pause pause) {
        return new ServerEnvironment(accept, threads, pause, new SystemClock());
    }

    /** Connects and reads until the server closes the connection; returns the bytes received. */
    private static int bytesUntilClosed(int port) throws IOException {
        try (Socket s = new Socket(InetAddress.getLoopbackAddress(), port)) {
            s.setSoTimeout(10_000);
            InputStream in = s.getInputStream();
            int n = 0;
            try {
                while (in.read() >= 0) {
                    n++;
                }
            } catch (SocketException reset) {
                // closed with data unread on the server side: a reset, also a refusal
            }
            return n;
        }
    }

    @Test
    void failingAcceptsBackOffExponentiallyAndLogOncePerEpisode() throws Exception {
        AtomicInteger failuresLeft = new AtomicInteger(12);
        List<Long> pausesNs = Collections.synchronizedList(new ArrayList<>());
        ServerEnvironment.Accept fdExhausted = s -> {
            if (failuresLeft.getAndDecrement() > 0) {
                throw new SocketException("Too many open files");
            }
            return s.accept();
        };
        try (LogCapture log = new LogCapture(ClientAcceptor.class)) {
            server = PlayerSimServer.startManual(PlayerSimServerTest.world(), ServerConfig.defaults(0),
                    env(fdExhausted, Thread::new, pausesNs::add));
            try (RawClient c = new RawClient(server.port())) {
                assertEquals(PlayerSimServer.VERSION, c.banner, "served once accepting works again");
            }
            assertEquals(List.of(1L, 2L, 4L, 8L, 16L, 32L, 64L, 128L, 256L, 512L, 1000L, 1000L),
                    pausesNs.stream().map(ns -> ns / MS).toList(), "bounded exponential back-off, ms");
            assertEquals(1, log.matching("accept failed").size(), "one warning for the episode: " + log.lines());
            assertTrue(log.matching("accept failed").get(0).contains("Too many open files"));
            assertEquals(List.of("INFO rtaware-sim: accepting clients again after 12 failed accepts"),
                    log.matching("accepting clients again"));
        }
    }

    @Test
    void anErrorOfTheAcceptLoopIsLoggedAndTheLoopGoesOnToServeTheNextClient() throws Exception {
        AtomicInteger accepts = new AtomicInteger();
        ServerEnvironment.Accept firstFails = s -> {
            Socket socket = s.accept();
            if (accepts.incrementAndGet() == 1) {
                socket.close();
                throw new IllegalStateException("a fault of the accept loop");
            }
            return socket;
        };
        try (LogCapture log = new LogCapture(PlayerSimServer.class)) {
            server = PlayerSimServer.startManual(PlayerSimServerTest.world(), ServerConfig.defaults(0),
                    env(firstFails, Thread::new, ns -> { }));
            assertEquals(0, bytesUntilClosed(server.port()), "the first client: closed by the fault, nothing sent");
            try (RawClient c = new RawClient(server.port())) {
                assertEquals(PlayerSimServer.VERSION, c.banner, "the loop went on: the next client is served");
            }
            assertEquals(1, log.matching("accepting a client failed").size(), log.lines().toString());
            assertTrue(log.matching("accepting a client failed").get(0).contains("a fault of the accept loop"),
                    log.lines().toString());
        }
    }

    @Test
    void aClientWhoseThreadsCannotStartIsRefusedAndTheNextIsServed() throws Exception {
        AtomicInteger calls = new AtomicInteger();
        java.util.concurrent.ThreadFactory secondFails = r -> {
            if (calls.incrementAndGet() == 2) { // the first client's reader, after its writer started
                throw new OutOfMemoryError("unable to create native thread: possibly out of memory");
            }
            return new Thread(r);
        };
        try (LogCapture log = new LogCapture(ClientAcceptor.class)) {
            server = PlayerSimServer.startManual(PlayerSimServerTest.world(), ServerConfig.defaults(0),
                    env(ServerSocket::accept, secondFails, ns -> { }));
            assertTrue(bytesUntilClosed(server.port()) <= 32, "refused: closed after the banner at most");
            try (RawClient c = new RawClient(server.port())) {
                RawClient.Msg list = c.request(Interfaces.PLAYER, 0, Subtypes.PLAYER_REQ_DEVLIST, w -> { });
                assertEquals(MessageType.RESP_ACK, list.header().type(), "the next client is served");
                assertEquals(1, server.clientCount());
            }
            assertEquals(1, log.matching("cannot start its threads").size(), log.lines().toString());
        }
    }

    @Test
    void clientsBeyondTheCapAreRefusedUntilOneLeaves() throws Exception {
        try (LogCapture log = new LogCapture(ClientAcceptor.class)) {
            server = PlayerSimServer.startManual(PlayerSimServerTest.world(),
                    ServerConfig.defaults(0).withLimits(2, ServerConfig.DEFAULT_MAX_RULES, 10_000 * MS));
            RawClient a = new RawClient(server.port());
            try (RawClient b = new RawClient(server.port())) {
                assertEquals(0, bytesUntilClosed(server.port()), "third client: closed, no banner");
                assertEquals(0, bytesUntilClosed(server.port()), "fourth client: closed, no banner");
                assertEquals(2, server.clientCount());
                a.close();
                Waits.until(() -> server.clientCount() == 1, Duration.ofSeconds(10), "the server notices the client that left");
                try (RawClient c = new RawClient(server.port())) {
                    assertEquals(PlayerSimServer.VERSION, c.banner, "a freed slot is taken");
                    assertEquals(MessageType.RESP_ACK,
                            c.request(Interfaces.PLAYER, 0, Subtypes.PLAYER_REQ_DEVLIST, w -> { }).header().type());
                }
                assertEquals(MessageType.RESP_ACK,
                        b.request(Interfaces.PLAYER, 0, Subtypes.PLAYER_REQ_DEVLIST, w -> { }).header().type());
            }
            assertEquals(1, log.matching("refusing client").size(), "once per episode: " + log.lines());
            assertTrue(log.matching("refusing client").get(0).contains("2 clients connected"));
            assertEquals(1, log.matching("after 2 were refused").size(), log.lines().toString());
        }
    }

    private static RawClient.Msg addRule(RawClient c, ReplaceRule rule) throws IOException {
        return c.request(Interfaces.PLAYER, 0, Subtypes.PLAYER_REQ_ADD_REPLACE_RULE,
                w -> PlayerCodec.writeReplaceRule(w, rule));
    }

    @Test
    void rulesBeyondTheCapAreNackedAndAnEqualRuleReplacesItsElder() throws Exception {
        server = PlayerSimServer.startManual(PlayerSimServerTest.world(),
                ServerConfig.defaults(0).withLimits(ServerConfig.DEFAULT_MAX_CLIENTS, 3, 10_000 * MS));
        try (LogCapture log = new LogCapture(ClientSession.class); RawClient c = new RawClient(server.port())) {
            PlayerSimServerTest.dataMode(c, Subtypes.DATAMODE_PULL);
            ReplaceRule rangerIgnored = new ReplaceRule(Interfaces.RANGER, -1, MessageType.DATA, -1,
                    Subtypes.REPLACE_IGNORE);
            assertEquals(MessageType.RESP_ACK, addRule(c, ReplaceRule.latestDataOnly()).header().type());
            assertEquals(MessageType.RESP_ACK, addRule(c, rangerIgnored).header().type());
            assertEquals(MessageType.RESP_ACK, addRule(c, new ReplaceRule(Interfaces.LASER, 0, -1, -1,
                    Subtypes.REPLACE_ACCEPT)).header().type());
            for (int i = 0; i < 5; i++) {
                assertEquals(MessageType.RESP_NACK, addRule(c, new ReplaceRule(Interfaces.POSITION2D, 0, -1, i,
                        Subtypes.REPLACE_IGNORE)).header().type(), "a fourth distinct rule");
            }
            assertEquals(1, log.matching("replace rules").size(), "logged once per client: " + log.lines());
            // the same criteria again: replaces the elder rule (and is now the newest), not a fourth rule
            assertEquals(MessageType.RESP_ACK, addRule(c, new ReplaceRule(Interfaces.RANGER, -2, MessageType.DATA, -1,
                    Subtypes.REPLACE_ACCEPT)).header().type());
            PlayerSimServerTest.subscribe(c, Interfaces.POSITION2D);
            PlayerSimServerTest.subscribe(c, Interfaces.RANGER);
            for (int i = 0; i < 100; i++) {
                server.step(10 * MS);
            }
            List<RawClient.Msg> round = c.round();
            assertEquals(1, round.stream().filter(m -> m.header().interf() == Interfaces.POSITION2D).count(),
                    "latest odometry only");
            assertEquals(20, round.stream().filter(m -> m.header().interf() == Interfaces.RANGER).count(),
                    "ranger accepted: 10 scans x (RANGE + INTNS)");
        }
    }

    @Test
    void aClientStallingInsideAMessageIsDroppedWhileAnIdleOneStays() throws Exception {
        server = PlayerSimServer.startManual(PlayerSimServerTest.world(),
                ServerConfig.defaults(0).withLimits(ServerConfig.DEFAULT_MAX_CLIENTS, ServerConfig.DEFAULT_MAX_RULES,
                        200 * MS));
        try (LogCapture log = new LogCapture(ClientSession.class);
             RawClient idle = new RawClient(server.port()); RawClient stalled = new RawClient(server.port())) {
            stalled.sendRaw(new byte[20]); // half a header, then nothing
            IOException e = assertThrows(IOException.class, stalled::read, "the stalled client is disconnected");
            assertTrue(!(e instanceof java.net.SocketTimeoutException), "dropped by the server, not timed out here: " + e);
            assertEquals(1, log.matching("did not complete within 200 ms").size(), log.lines().toString() + " " + e);
            assertEquals(MessageType.RESP_ACK,
                    idle.request(Interfaces.PLAYER, 0, Subtypes.PLAYER_REQ_DEVLIST, w -> { }).header().type(),
                    "a client idle between messages (longer than the timeout) is served");
        }
    }
}
