package io.rtaware.zenoh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.testing.Requires;
import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.function.Executable;

/**
 * The native layer's handles: a close racing a waiting {@code take}, a double close, a use after
 * close and a handle of the wrong kind end in a {@link ZenohException} or a defined result, never
 * in freed memory (before handles were table entries, each of these used or freed freed memory).
 */
@Requires(NativeZenohLayer.class)
class ZenohHandleSafetyTest {

    private static final long LONG_WAIT_NS = TimeUnit.SECONDS.toNanos(30);

    private static void assertClosedError(Executable call, String what) {
        ZenohException e = assertThrows(ZenohException.class, call, what);
        assertTrue(e.getMessage().contains("closed"), what + ": " + e.getMessage());
    }

    @Test
    void aDoubleCloseAndAUseAfterCloseOfEveryHandleThrow() throws Exception {
        long session = NativeZenoh.open("peer", new String[0], new String[] {ZenohConfig.LOOPBACK_ANY_PORT},
                false, 1000);
        long publisher = NativeZenoh.declarePublisher(session, "safety/p");
        long mailbox = NativeZenoh.newMailbox(2);
        long subscriber = NativeZenoh.declareSubscriber(session, "safety/p", mailbox, 0);
        long token = NativeZenoh.declareToken(session, "@safety/t");
        ByteBuffer buffer = ByteBuffer.allocateDirect(16);

        NativeZenoh.undeclarePublisher(publisher);
        assertClosedError(() -> NativeZenoh.undeclarePublisher(publisher), "publisher closed twice");
        assertClosedError(() -> NativeZenoh.put(publisher, buffer, 1, buffer, -1), "put after close");

        NativeZenoh.undeclareSubscriber(subscriber);
        assertClosedError(() -> NativeZenoh.undeclareSubscriber(subscriber), "subscriber closed twice");

        NativeZenoh.closeMailbox(mailbox);
        assertClosedError(() -> NativeZenoh.closeMailbox(mailbox), "mailbox closed twice");
        assertClosedError(() -> NativeZenoh.take(mailbox, 0, buffer, ByteBuffer.allocateDirect(1),
                ByteBuffer.allocateDirect(12)), "take after close");
        assertClosedError(() -> NativeZenoh.overflowed(mailbox), "overflowed after close");

        NativeZenoh.undeclareToken(token);
        assertClosedError(() -> NativeZenoh.undeclareToken(token), "token closed twice");

        NativeZenoh.close(session);
        assertClosedError(() -> NativeZenoh.close(session), "session closed twice");
        assertClosedError(() -> NativeZenoh.zid(session), "zid after close");
        assertClosedError(() -> NativeZenoh.declarePublisher(session, "x"), "declaring on a closed session");
        assertClosedError(() -> NativeZenoh.close(0), "handle 0");
    }

    @Test
    void aHandleOfAnotherKindIsRefusedAndKeepsWorking() throws Exception {
        try (ZenohSession s = ZenohSession.open(ZenohConfig.loopbackPeer())) {
            ZenohPublisher publisher = s.declarePublisher("safety/kind");
            long mailbox = NativeZenoh.newMailbox(1);
            ByteBuffer buffer = ByteBuffer.allocateDirect(16);
            ZenohException e = assertThrows(ZenohException.class, () -> NativeZenoh.closeMailbox(4_000_000_000L + mailbox));
            assertTrue(e.getMessage().contains("closed or was never opened"), e.getMessage());
            e = assertThrows(ZenohException.class, () -> NativeZenoh.undeclarePublisher(mailbox));
            assertTrue(e.getMessage().contains("not a Zenoh publisher"), e.getMessage());
            SampleBuffer into = new SampleBuffer(16, 0);
            assertEquals(0, NativeZenoh.take(mailbox, 0, into.payload(), into.attachment(), into.info()),
                    "the mailbox survived the wrong close");
            e = assertThrows(ZenohException.class, () -> NativeZenoh.take(mailbox, 0, buffer, buffer, into.info()));
            assertTrue(e.getMessage().contains("must not share memory"), e.getMessage());
            e = assertThrows(ZenohException.class, () -> NativeZenoh.take(mailbox, 0, buffer,
                    buffer.slice(8, 8), into.info()));
            assertTrue(e.getMessage().contains("must not share memory"), "a slice of the payload: " + e.getMessage());
            NativeZenoh.closeMailbox(mailbox);
            publisher.put(buffer, 1, null, 0);
        }
    }

    @Test
    void theJavaObjectsAreIdempotentAndThrowWhenUsedAfterClose() throws Exception {
        ZenohSession s = ZenohSession.open(ZenohConfig.loopbackPeer());
        ZenohMailbox mailbox = s.newMailbox(2);
        ZenohPublisher publisher = s.declarePublisher("safety/java");
        s.close();
        s.close();
        mailbox.close();
        publisher.close();
        SampleBuffer into = new SampleBuffer(4, 0);
        assertClosedError(() -> mailbox.take(0, into), "take on a closed mailbox");
        assertClosedError(() -> mailbox.subscribe("safety/java", 0), "subscribe on a closed mailbox");
        assertClosedError(() -> publisher.put(ByteBuffer.allocateDirect(1), 1, null, 0), "put on a closed publisher");
        assertClosedError(() -> s.newMailbox(1), "a mailbox of a closed session");
    }

    @Test
    @Timeout(value = 120, unit = TimeUnit.SECONDS)
    void closingAMailboxWhileItsReaderWaitsAndSamplesArriveIsSafe() throws Exception {
        int rounds = 300;
        try (ZenohSession s = ZenohSession.open(ZenohConfig.loopbackPeer())) {
            ZenohPublisher publisher = s.declarePublisher("safety/race");
            AtomicBoolean publishing = new AtomicBoolean(true);
            AtomicReference<Throwable> publisherFailure = new AtomicReference<>();
            Thread writer = new Thread(() -> {
                ByteBuffer payload = ByteBuffer.allocateDirect(64);
                try {
                    while (publishing.get()) {
                        publisher.put(payload, 64, null, 0);
                    }
                } catch (ZenohException e) {
                    publisherFailure.set(e);
                }
            }, "safety-writer");
            writer.start();
            int wokenWithClosed = 0;
            int refusedAfterClose = 0;
            for (int round = 0; round < rounds; round++) {
                ZenohMailbox mailbox = s.newMailbox(4);
                mailbox.subscribe("safety/race", round);
                List<Object> outcomes = new ArrayList<>();
                Thread reader = new Thread(() -> {
                    SampleBuffer into = new SampleBuffer(64, 0);
                    try {
                        ZenohMailbox.Take took;
                        do {
                            took = mailbox.take(LONG_WAIT_NS, into);
                        } while (took != ZenohMailbox.Take.CLOSED);
                        synchronized (outcomes) {
                            outcomes.add(took);
                        }
                    } catch (ZenohException e) {
                        synchronized (outcomes) {
                            outcomes.add(e);
                        }
                    }
                }, "safety-reader");
                reader.start();
                mailbox.close();
                reader.join();
                synchronized (outcomes) {
                    assertEquals(1, outcomes.size(), "round " + round);
                    Object outcome = outcomes.get(0);
                    if (outcome instanceof ZenohException e) {
                        assertTrue(e.getMessage().contains("closed"), "round " + round + ": " + e.getMessage());
                        refusedAfterClose++;
                    } else {
                        assertEquals(ZenohMailbox.Take.CLOSED, outcome, "round " + round);
                        wokenWithClosed++;
                    }
                }
            }
            publishing.set(false);
            writer.join();
            assertEquals(null, publisherFailure.get(), "the publisher kept working");
            assertEquals(rounds, wokenWithClosed + refusedAfterClose);
        }
    }
}
