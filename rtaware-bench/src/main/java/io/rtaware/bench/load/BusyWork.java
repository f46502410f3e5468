package io.rtaware.bench.load;

/**
 * Real CPU work of a requested duration: a busy loop of integer arithmetic whose iteration
 * count is calibrated once against the wall clock, so the work burns CPU like a real task does
 * (sleeping would free the core and hide contention). Immutable after calibration; thread-safe.
 */
public final class BusyWork {

    private static final long CALIBRATION_ITERATIONS = 2_000_000;
    private static volatile long sink;

    private final double iterationsPerNs;

    private BusyWork(double iterationsPerNs) {
        this.iterationsPerNs = iterationsPerNs;
    }

    /**
     * Measures this machine's loop speed: warms the loop up, then keeps the fastest of several
     * timed rounds (the slower ones were interrupted by the OS).
     *
     * @return calibrated work
     */
    public static BusyWork calibrate() {
        double best = 0;
        for (int round = 0; round < 30; round++) {
            long t0 = System.nanoTime();
            spin(CALIBRATION_ITERATIONS);
            long elapsed = System.nanoTime() - t0;
            if (elapsed > 0) {
                best = Math.max(best, (double) CALIBRATION_ITERATIONS / elapsed);
            }
        }
        return new BusyWork(best);
    }

    /** @return loop iterations per nanosecond measured on this machine */
    public double iterationsPerNs() {
        return iterationsPerNs;
    }

    /**
     * Burns about {@code wallNs} of CPU time on the calling thread.
     *
     * @param wallNs the duration of work in wall-clock nanoseconds on an idle core
     */
    public void burn(long wallNs) {
        if (wallNs > 0) {
            spin((long) (wallNs * iterationsPerNs));
        }
    }

    private static void spin(long iterations) {
        long x = 0x9E3779B97F4A7C15L;
        for (long i = 0; i < iterations; i++) {
            x ^= x << 13;
            x ^= x >>> 7;
            x ^= x << 17;
        }
        sink = x;
    }
}
