package io.rtaware.record.ring;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** The rings' contract: claim, fill, publish; one consumer drains in position order; a full ring refuses. */
@Timeout(60)
class SlotRingTest {

    /** A slot: which producer wrote it, and its record number among that producer's. */
    private static final class Box {
        int producer;
        long value;
    }

    private static long offer(SlotRing<Box> ring, int producer, long value) {
        long position = ring.claim();
        if (position >= 0) {
            Box box = ring.slot(position);
            box.producer = producer;
            box.value = value;
            ring.publish(position);
        }
        return position;
    }

    /** Drains into a list of values, each paired with its position. */
    private static List<String> drain(SlotRing<Box> ring) throws IOException {
        List<String> read = new ArrayList<>();
        ring.drain((box, position, out, unused) -> out.add(position + "=" + box.value), read, null);
        return read;
    }

    @Test
    void aFullRingRefusesTheClaimUntilTheConsumerFreesASlot() throws IOException {
        SingleProducerRing<Box> ring = new SingleProducerRing<>(2, i -> new Box());
        assertEquals(0, offer(ring, 0, 10));
        assertEquals(1, offer(ring, 0, 11));
        assertEquals(-1, offer(ring, 0, 12), "two slots, both unread: the record is dropped");
        assertEquals(List.of("0=10", "1=11"), drain(ring));
        assertEquals(2, offer(ring, 0, 13), "positions go on after a drop; slots are reused");
        assertEquals(List.of("2=13"), drain(ring));
        assertEquals(List.of(), drain(ring), "nothing twice");
    }

    @Test
    void aPositionClaimedButNeverPublishedIsClaimedAgainOnASingleProducerRing() throws IOException {
        SingleProducerRing<Box> ring = new SingleProducerRing<>(4, i -> new Box());
        long abandoned = ring.claim(); // e.g. the copy into the slot threw
        assertEquals(abandoned, ring.claim(), "the same position again");
        assertEquals(abandoned, offer(ring, 0, 7));
        assertEquals(List.of("0=7"), drain(ring));
    }

    @Test
    void theConsumerReadsInPositionOrderAndStopsAtTheFirstUnpublishedPosition() throws IOException {
        MultiProducerRing<Box> ring = new MultiProducerRing<>(4, i -> new Box());
        long first = ring.claim();
        long second = ring.claim();
        ring.slot(second).value = 2;
        ring.publish(second); // a faster producer publishes first
        assertEquals(List.of(), drain(ring), "position 0 is claimed but not yet filled: nothing is read past it");
        ring.slot(first).value = 1;
        ring.publish(first);
        assertEquals(List.of("0=1", "1=2"), drain(ring));
    }

    @Test
    void aDrainEndsAtWhatWasClaimedWhenItBeganHoweverFastTheProducersGoOn() throws IOException {
        for (SlotRing<Box> ring : List.of(new SingleProducerRing<Box>(8, i -> new Box()),
                new MultiProducerRing<Box>(8, i -> new Box()))) {
            offer(ring, 0, 1);
            offer(ring, 0, 2);
            List<Long> read = new ArrayList<>();
            int n = ring.drain((box, position, out, unused) -> {
                out.add(box.value);
                offer(ring, 0, 10 + box.value); // a producer publishing while the consumer reads
            }, read, null);
            assertEquals(2, n, ring.getClass().getSimpleName());
            assertEquals(List.of(1L, 2L), read, "the records published during the drain wait for the next one");
            read.clear();
            ring.drain((box, position, out, unused) -> out.add(box.value), read, null);
            assertEquals(List.of(11L, 12L), read, ring.getClass().getSimpleName());
        }
    }

    @Test
    void aReaderThatFailsLeavesItsSlotUnreadAndDiscardFreesEveryPublishedSlot() throws IOException {
        SingleProducerRing<Box> ring = new SingleProducerRing<>(3, i -> new Box());
        offer(ring, 0, 1);
        offer(ring, 0, 2);
        offer(ring, 0, 3);
        IOException full = new IOException("disk full");
        IOException thrown = assertThrows(IOException.class, () -> ring.drain((box, position, a, b) -> {
            if (box.value == 2) {
                throw full;
            }
        }, null, null));
        assertSame(full, thrown);
        List<Long> freed = new ArrayList<>();
        assertEquals(2, ring.discard(box -> freed.add(box.value)));
        assertEquals(List.of(2L, 3L), freed, "each freed slot is handed over first");
        assertEquals(3, offer(ring, 0, 4), "the producer goes on after the discard");
    }

    @Test
    void slotsAreMadeOnceAndReusedAndACapacityBelowOneIsRefused() {
        List<Box> made = new ArrayList<>();
        SingleProducerRing<Box> ring = new SingleProducerRing<>(2, i -> {
            Box b = new Box();
            made.add(b);
            return b;
        });
        assertEquals(2, ring.capacity());
        assertSame(made.get(0), ring.slot(0));
        assertSame(made.get(1), ring.slot(1));
        assertSame(made.get(0), ring.slot(2), "position 2 is slot 0 again");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new MultiProducerRing<>(0, i -> new Box()));
        assertTrue(e.getMessage().contains("got 0"), e.getMessage());
    }

    @Test
    void oneProducerThreadAndTheConsumerThreadPassEveryRecordOnceInOrder() throws Exception {
        assertEveryRecordOnceInEachProducersOrder(new SingleProducerRing<>(64, i -> new Box()), 1, 200_000);
    }

    @Test
    void manyProducerThreadsAtOnceAndTheConsumerThreadPassEveryRecordOnceInEachProducersOrder() throws Exception {
        assertEveryRecordOnceInEachProducersOrder(new MultiProducerRing<>(64, i -> new Box()), 4, 100_000);
    }

    /**
     * Producers retry a refused claim until it succeeds, so every record passes; the consumer
     * checks that each producer's records come whole, once, and in the order it published them.
     */
    private static void assertEveryRecordOnceInEachProducersOrder(SlotRing<Box> ring, int producers, long perProducer)
            throws Exception {
        CountDownLatch go = new CountDownLatch(1);
        AtomicReference<Throwable> failed = new AtomicReference<>();
        List<Thread> threads = new ArrayList<>();
        for (int p = 0; p < producers; p++) {
            int producer = p;
            Thread t = new Thread(() -> {
                try {
                    go.await();
                    for (long v = 0; v < perProducer; v++) {
                        while (offer(ring, producer, v) < 0) {
                            Thread.yield(); // full: wait for the consumer, as a test may
                        }
                    }
                } catch (Throwable e) {
                    failed.compareAndSet(null, e);
                }
            }, "ring-producer-" + p);
            t.setDaemon(true);
            t.start();
            threads.add(t);
        }
        long[] nextValue = new long[producers];
        long[] nextPosition = {0};
        long total = producers * perProducer;
        go.countDown();
        long read = 0;
        while (read < total && failed.get() == null) {
            int n = ring.drain((box, position, expected, positions) -> {
                if (position != positions[0]++) {
                    throw new AssertionError("position " + position + " out of order");
                }
                if (box.value != expected[box.producer]++) {
                    throw new AssertionError("producer " + box.producer + ": record " + box.value
                            + " where " + (expected[box.producer] - 1) + " was next");
                }
            }, nextValue, nextPosition);
            if (n == 0) {
                Thread.yield();
            }
            read += n;
        }
        for (Thread t : threads) {
            t.join(TimeUnit.SECONDS.toMillis(30));
        }
        assertNull(failed.get(), "no producer failed");
        long[] all = new long[producers];
        Arrays.fill(all, perProducer);
        assertArrayEquals(all, nextValue, "every producer's records, each once");
        assertEquals(total, read);
        assertEquals(0, ring.drain((box, position, a, b) -> { }, null, null), "nothing more");
    }
}
