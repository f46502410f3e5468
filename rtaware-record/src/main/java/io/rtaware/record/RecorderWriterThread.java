package io.rtaware.record;

import java.io.IOException;
import java.util.List;
import java.util.concurrent.locks.LockSupport;

/**
 * The recorder's one writer thread: drains the rings into the sink until stopped, then once
 * more. A write that fails ends the writing (the reason kept for the recording's statistics) and
 * the thread goes on emptying the rings unwritten, so producers only ever drop, never block.
 */
final class RecorderWriterThread {

    private static final long IDLE_PARK_NS = 1_000_000;

    private final List<RecorderRing> rings;
    private final MessageSink sink;
    private final WriterScratch scratch = new WriterScratch();
    private final Thread thread;
    private volatile boolean stopping;
    private volatile String failure;

    RecorderWriterThread(List<RecorderRing> rings, MessageSink sink) {
        this.rings = List.copyOf(rings);
        this.sink = sink;
        thread = new Thread(this::loop, "rtaware-recorder");
        thread.setDaemon(true);
    }

    void start() {
        thread.start();
    }

    private void loop() {
        try {
            while (true) {
                boolean finishing = stopping;
                int written = 0;
                for (RecorderRing ring : rings) {
                    written += ring.drain(sink, scratch);
                }
                if (written == 0) {
                    if (finishing) {
                        return;
                    }
                    LockSupport.parkNanos(IDLE_PARK_NS);
                }
            }
        } catch (IOException | RuntimeException e) {
            failure = e.getMessage() == null ? e.toString() : e.getMessage();
            while (!stopping) {
                for (RecorderRing ring : rings) {
                    ring.discard();
                }
                LockSupport.parkNanos(IDLE_PARK_NS);
            }
        }
    }

    /**
     * Stops the thread after it has written everything handed over, and waits for it.
     *
     * @return why writing failed, or null
     */
    String stopAndJoin() {
        stopping = true;
        LockSupport.unpark(thread);
        try {
            thread.join();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return failure;
    }
}
