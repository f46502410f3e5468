package io.rtaware.bench.load;

import java.util.ArrayList;
import java.util.List;

/**
 * {@code --load N}: N daemon threads that spin on arithmetic for as long as the bench runs, so
 * the tasks compete for the cores. Started by {@link #start(int)}, stopped by {@link #close()}.
 * Thread-safe.
 */
public final class CpuLoad implements AutoCloseable {

    private final List<Thread> threads = new ArrayList<>();
    private volatile boolean running = true;
    private volatile double sink;

    private CpuLoad() {
    }

    /**
     * @param count busy threads to start; 0 starts none
     * @return the running load
     */
    public static CpuLoad start(int count) {
        CpuLoad load = new CpuLoad();
        for (int i = 0; i < count; i++) {
            Thread thread = new Thread(load::spin, "bench-load-" + i);
            thread.setDaemon(true);
            load.threads.add(thread);
            thread.start();
        }
        return load;
    }

    private void spin() {
        double x = 1.0;
        while (running) {
            for (int i = 0; i < 100_000; i++) {
                x = Math.sqrt(x + i);
            }
            sink = x;
        }
    }

    @Override
    public void close() throws InterruptedException {
        running = false;
        for (Thread thread : threads) {
            thread.join();
        }
    }
}
