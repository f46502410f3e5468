package io.rtaware.foxglove;

import java.util.function.BooleanSupplier;

/** Waiting for a condition another thread makes true, bounded so that a broken test fails instead of hanging. */
final class TestWaits {

    private static final long LIMIT_NS = 30_000_000_000L;

    private TestWaits() {
    }

    /**
     * Returns once {@code condition} holds; fails after 30 s of wall time.
     *
     * @param condition checked until it is true
     * @param what what is waited for, in the failure's message
     */
    static void until(BooleanSupplier condition, String what) throws InterruptedException {
        long end = System.nanoTime() + LIMIT_NS;
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() - end > 0) {
                throw new AssertionError("not within 30 s: " + what);
            }
            Thread.sleep(1);
        }
    }
}
