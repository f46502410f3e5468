package io.rtaware.core.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;

/** {@link Waits#until}: returns once the condition holds, fails naming what was awaited. */
class WaitsTest {

    @Test
    void aConditionThatHoldsReturnsAtOnceAskedOnce() throws Exception {
        AtomicInteger asked = new AtomicInteger();
        Waits.until(() -> asked.incrementAndGet() > 0, Duration.ZERO, "nothing");
        assertEquals(1, asked.get());
    }

    @Test
    void aConditionNeverTrueFailsAtTheBoundNamingWhatWasAwaited() {
        AtomicInteger asked = new AtomicInteger();
        AssertionError e = assertThrows(AssertionError.class,
                () -> Waits.until(() -> asked.incrementAndGet() < 0, Duration.ZERO, "the peer's ready line"));
        assertEquals("not within 0 ms: the peer's ready line", e.getMessage());
        assertEquals(2, asked.get(), "asked once, and once more at the bound");
    }

    @Test
    void returnsOnceAnotherThreadMakesItTrue() throws Exception {
        AtomicBoolean done = new AtomicBoolean();
        CountDownLatch askedOnce = new CountDownLatch(1);
        Thread other = new Thread(() -> {
            try {
                askedOnce.await();
            } catch (InterruptedException e) {
                return;
            }
            done.set(true);
        });
        other.start();
        Waits.until(() -> {
            askedOnce.countDown();
            return done.get();
        }, Duration.ofMinutes(1), "the other thread's flag");
        assertTrue(done.get());
        other.join();
    }

    @Test
    void theWordsMadeAtTheFailureSayWhatWasSeen() {
        AtomicInteger asked = new AtomicInteger();
        AssertionError e = assertThrows(AssertionError.class, () -> Waits.until(() -> asked.incrementAndGet() < 0,
                Duration.ZERO, () -> "a negative count; asked " + asked.get() + " times"));
        assertEquals("not within 0 ms: a negative count; asked 2 times", e.getMessage());
    }

    @Test
    void whatTheConditionThrowsEndsTheWait() {
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> Waits.until(() -> {
            throw new IllegalStateException("the peer exited");
        }, Duration.ofMinutes(1), "the peer's line"));
        assertEquals("the peer exited", e.getMessage());
    }

    @Test
    void anInterruptedWaitFailsAndKeepsTheInterrupt() {
        Thread.currentThread().interrupt();
        AssertionError e = assertThrows(AssertionError.class,
                () -> Waits.until(() -> false, Duration.ofMinutes(1), "a flag"));
        assertEquals("interrupted while awaiting: a flag", e.getMessage());
        assertTrue(Thread.interrupted(), "the interrupt is kept for the caller");
    }
}
