package io.rtaware.core.testing;

import java.time.Duration;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import java.util.function.Supplier;
import org.junit.jupiter.api.Assertions;

/**
 * Waiting for what another process or thread makes true when it offers nothing to wait on (a
 * child process's output, a peer on the network, a server's count of clients): the condition is
 * asked about every millisecond, and a bound on the wall time turns a broken test into a failure
 * that names what was awaited instead of a hang. The bound is never a claim about speed: it is
 * far above what the awaited thing takes on a loaded machine. Where the code under test offers a
 * latch, a future or a stepped clock, a test uses that instead.
 */
public final class Waits {

    private static final long POLL_NS = TimeUnit.MILLISECONDS.toNanos(1);

    /** A condition that may do a step of its own before it answers (publish once more, run a cycle). */
    @FunctionalInterface
    public interface Condition {
        /**
         * @return whether what is awaited has happened
         * @throws Exception if asking fails; the wait ends with it
         */
        boolean holds() throws Exception;
    }

    private Waits() {
    }

    /**
     * Returns once {@code condition} holds; asks it at least once, and once more at the bound.
     *
     * @param condition asked until it is true
     * @param timeout the bound on the wall time
     * @param awaited what is awaited, in words, for the failure's message
     * @throws org.opentest4j.AssertionFailedError if it does not hold within {@code timeout}, or the
     *     thread is interrupted
     * @throws Exception what the condition threw
     */
    public static void until(Condition condition, Duration timeout, String awaited) throws Exception {
        until(condition, timeout, () -> awaited);
    }

    /**
     * As {@link #until(Condition, Duration, String)}, with the words made at the failure (they may
     * say what was seen by then).
     *
     * @param condition asked until it is true
     * @param timeout the bound on the wall time
     * @param awaited what is awaited, and what was seen, for the failure's message
     * @throws org.opentest4j.AssertionFailedError if it does not hold within {@code timeout}, or the
     *     thread is interrupted
     * @throws Exception what the condition threw
     */
    public static void until(Condition condition, Duration timeout, Supplier<String> awaited) throws Exception {
        long endNs = System.nanoTime() + timeout.toNanos();
        while (!condition.holds()) {
            if (System.nanoTime() - endNs >= 0) {
                if (condition.holds()) {
                    return;
                }
                Assertions.fail("not within " + timeout.toMillis() + " ms: " + awaited.get());
            }
            LockSupport.parkNanos(POLL_NS);
            if (Thread.interrupted()) {
                Thread.currentThread().interrupt();
                Assertions.fail("interrupted while awaiting: " + awaited.get());
            }
        }
    }
}
