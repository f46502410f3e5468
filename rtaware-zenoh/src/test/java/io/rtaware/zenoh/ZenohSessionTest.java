package io.rtaware.zenoh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.testing.Requires;
import java.net.ServerSocket;
import java.nio.ByteBuffer;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/** Two sessions on loopback: the real Zenoh engine behind the JNI layer. */
@Requires(NativeZenohLayer.class)
class ZenohSessionTest {

    private static final long WAIT_NS = TimeUnit.SECONDS.toNanos(10);

    private static int freePort() throws Exception {
        try (ServerSocket s = new ServerSocket(0)) {
            return s.getLocalPort();
        }
    }

    @Test
    void samplesAndAttachmentsCrossFromOneSessionToAnother() throws Exception {
        String endpoint = "tcp/127.0.0.1:" + freePort();
        ZenohConfig base = ZenohConfig.loopbackPeer();
        try (ZenohSession a = ZenohSession.open(base.withListen(List.of(endpoint)));
             ZenohSession b = ZenohSession.open(base.withConnect(List.of(endpoint)))) {
            ZenohMailbox mailbox = b.newMailbox(8);
            mailbox.subscribe("test/**", 7);
            ZenohPublisher pub = a.declarePublisher("test/topic");
            ByteBuffer payload = ByteBuffer.allocateDirect(16);
            payload.put(0, (byte) 1).put(1, (byte) 2).put(2, (byte) 3);
            ByteBuffer attachment = ByteBuffer.allocateDirect(4);
            attachment.put(0, (byte) 9);
            SampleBuffer into = new SampleBuffer(64, 64);
            ZenohMailbox.Take took = ZenohMailbox.Take.TIMEOUT;
            // Subscriptions propagate asynchronously: publish until one arrives.
            for (int i = 0; i < 100 && took == ZenohMailbox.Take.TIMEOUT; i++) {
                pub.put(payload, 3, attachment, 1);
                took = mailbox.take(TimeUnit.MILLISECONDS.toNanos(100), into);
            }
            assertEquals(ZenohMailbox.Take.SAMPLE, took);
            assertEquals(7, into.channel());
            assertEquals(3, into.payloadLength());
            assertEquals(3, into.payload().get(2));
            assertEquals(1, into.attachmentLength());
            assertEquals(9, into.attachment().get(0));
            assertTrue(a.zid().matches("[0-9a-f]+"), a.zid());
        }
    }

    @Test
    void aSampleBiggerThanTheBufferIsReportedAndDropped() throws Exception {
        try (ZenohSession s = ZenohSession.open(ZenohConfig.loopbackPeer())) {
            ZenohMailbox mailbox = s.newMailbox(4);
            mailbox.subscribe("big", 0);
            ZenohPublisher pub = s.declarePublisher("big");
            ByteBuffer payload = ByteBuffer.allocateDirect(100);
            SampleBuffer into = new SampleBuffer(10, 0);
            pub.put(payload, 100, null, 0);
            assertEquals(ZenohMailbox.Take.TOO_LARGE, mailbox.take(WAIT_NS, into));
            assertEquals(100, into.payloadLength());
            assertEquals(-1, into.attachmentLength());
            assertEquals(ZenohMailbox.Take.TIMEOUT, mailbox.take(0, into));
        }
    }

    @Test
    void aFullMailboxDropsTheOldestAndCountsIt() throws Exception {
        try (ZenohSession s = ZenohSession.open(ZenohConfig.loopbackPeer())) {
            ZenohMailbox mailbox = s.newMailbox(2);
            mailbox.subscribe("seq", 0);
            ZenohPublisher pub = s.declarePublisher("seq");
            ByteBuffer payload = ByteBuffer.allocateDirect(1);
            for (int i = 0; i < 5; i++) {
                payload.put(0, (byte) i);
                pub.put(payload, 1, null, 0);
            }
            SampleBuffer into = new SampleBuffer(1, 0);
            assertEquals(ZenohMailbox.Take.SAMPLE, mailbox.take(WAIT_NS, into));
            assertEquals(3, into.payload().get(0), "the oldest samples go first");
            assertEquals(3, mailbox.overflowed());
        }
    }

    @Test
    void livelinessTokensAreListedUntilClosed() throws Exception {
        try (ZenohSession s = ZenohSession.open(ZenohConfig.loopbackPeer())) {
            LivelinessToken t = s.declareToken("@test_lv/0/node");
            assertEquals(List.of("@test_lv/0/node"), s.livelinessKeys("@test_lv/**", 1000));
            t.close();
            assertEquals(List.of(), s.livelinessKeys("@test_lv/**", 500));
        }
    }

    @Test
    void moreLivelinessTokensThanAskedForIsAnErrorNamingThePattern() throws Exception {
        try (ZenohSession s = ZenohSession.open(ZenohConfig.loopbackPeer())) {
            for (int i = 0; i < 4; i++) {
                s.declareToken("@cap_lv/" + i);
            }
            assertEquals(4, s.livelinessKeys("@cap_lv/**", 1000, 4).size(), "as many as allowed");
            ZenohException e = assertThrows(ZenohException.class, () -> s.livelinessKeys("@cap_lv/**", 1000, 3));
            assertEquals("more than 3 liveliness tokens match '@cap_lv/**'", e.getMessage());
            assertThrows(IllegalArgumentException.class, () -> s.livelinessKeys("@cap_lv/**", 1000, -1));
        }
    }

    @Test
    void anUnreachableRouterFailsTheOpen() throws Exception {
        ZenohConfig config = new ZenohConfig(ZenohConfig.Mode.PEER, List.of("tcp/127.0.0.1:" + freePort()),
                List.of(ZenohConfig.LOOPBACK_ANY_PORT), false, 500);
        ZenohException e = assertThrows(ZenohException.class, () -> ZenohSession.open(config).close());
        assertTrue(e.getMessage().contains("Zenoh"), e.getMessage());
        assertFalse(e.getMessage().contains(".rs:"), "no Rust source locations in messages: " + e.getMessage());
    }

    @Test
    void aClosedPublisherRefusesToPublish() throws Exception {
        try (ZenohSession s = ZenohSession.open(ZenohConfig.loopbackPeer())) {
            ZenohPublisher pub = s.declarePublisher("x");
            pub.close();
            assertThrows(ZenohException.class, () -> pub.put(ByteBuffer.allocateDirect(1), 1, null, 0));
            assertThrows(ZenohException.class, () -> s.declarePublisher("bad//key"));
        }
    }
}
