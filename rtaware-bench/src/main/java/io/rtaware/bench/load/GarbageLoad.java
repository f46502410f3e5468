package io.rtaware.bench.load;

import java.util.concurrent.locks.LockSupport;

/**
 * {@code --gc-pressure MBps}: a daemon thread that allocates garbage at a steady rate, in the
 * pattern of a busy application: byte arrays of 16 to 1039 bytes, most dropped at once (a ring
 * of 4096 very short-lived objects), one in 16 replacing an entry of a medium-lived set of up to
 * 64 MB (bounded to a quarter of the maximum heap), so old objects die too. It allocates in
 * 1 ms slices of {@code rate / 1000} bytes. Thread-safe.
 */
public final class GarbageLoad implements AutoCloseable {

    private static final long SLICE_NS = 1_000_000;
    private static final int MIN_BYTES = 16;
    private static final int SIZE_SPREAD = 1024;
    private static final int SHORT_LIVED = 4096;
    private static final long MEDIUM_LIVED_BYTES = 64L << 20;
    private static final int MEDIUM_EVERY = 16;

    private final double bytesPerSlice;
    private final Thread thread;
    private volatile boolean running = true;

    private GarbageLoad(double megabytesPerSecond) {
        this.bytesPerSlice = megabytesPerSecond * 1e6 * SLICE_NS / 1e9;
        this.thread = new Thread(this::allocate, "bench-garbage");
        thread.setDaemon(true);
    }

    /**
     * @param megabytesPerSecond allocation rate in MB/s (10^6 bytes); 0 starts nothing
     * @return the running load
     */
    public static GarbageLoad start(double megabytesPerSecond) {
        GarbageLoad load = new GarbageLoad(megabytesPerSecond);
        if (megabytesPerSecond > 0) {
            load.thread.start();
        }
        return load;
    }

    private void allocate() {
        long mediumBudget = Math.min(MEDIUM_LIVED_BYTES, Runtime.getRuntime().maxMemory() / 4);
        byte[][] shortLived = new byte[SHORT_LIVED][];
        byte[][] mediumLived = new byte[(int) Math.max(1, mediumBudget / (MIN_BYTES + SIZE_SPREAD / 2))][];
        long seed = 0x2545F4914F6CDD1DL;
        long next = System.nanoTime();
        double debt = 0;
        long count = 0;
        while (running) {
            debt += bytesPerSlice;
            while (debt > 0) {
                seed ^= seed << 13;
                seed ^= seed >>> 7;
                seed ^= seed << 17;
                byte[] garbage = new byte[MIN_BYTES + (int) ((seed >>> 1) % SIZE_SPREAD)];
                debt -= garbage.length;
                count++;
                if (count % MEDIUM_EVERY == 0) {
                    mediumLived[(int) ((seed >>> 33) % mediumLived.length)] = garbage;
                } else {
                    shortLived[(int) (count % SHORT_LIVED)] = garbage;
                }
            }
            next += SLICE_NS;
            long remaining;
            while ((remaining = next - System.nanoTime()) > 0 && running) {
                LockSupport.parkNanos(remaining);
            }
        }
    }

    @Override
    public void close() throws InterruptedException {
        running = false;
        if (thread.isAlive()) {
            thread.join();
        }
    }
}
