package io.rtaware.record;

import io.rtaware.core.agent.AgentThread;
import io.rtaware.core.agent.ThreadNames;
import java.io.IOException;
import java.util.List;
import org.agrona.concurrent.Agent;
import org.agrona.concurrent.SleepingIdleStrategy;

/**
 * The recorder's one writer thread ({@value ThreadNames#RECORDER}, an {@link AgentThread}): drains the
 * rings into the sink, idling {@value #IDLE_PARK_NS} ns when they are empty, until closed; then,
 * in its {@link Agent#onClose()}, drains until a pass writes nothing. A write that fails ends the
 * writing (the first reason kept for the recording's statistics) and the thread goes on emptying
 * the rings unwritten, so producers only ever drop, never block. Closing waits as long as the
 * last writes take and never interrupts the thread (an interrupt would close the file's channel).
 */
final class RecorderWriterThread {

    private static final long IDLE_PARK_NS = 1_000_000;

    private final List<RecorderRing> rings;
    private final MessageSink sink;
    private final WriterScratch scratch = new WriterScratch();
    private volatile AgentThread loop;
    private volatile String failure;

    RecorderWriterThread(List<RecorderRing> rings, MessageSink sink) {
        this.rings = List.copyOf(rings);
        this.sink = sink;
    }

    void start() {
        loop = AgentThread.start(new Writing(), new SleepingIdleStrategy(IDLE_PARK_NS), this::failed,
                AgentThread.CloseWait.UNTIL_CLOSED);
    }

    /** The writer's loop: a pass over the rings per duty cycle. */
    private final class Writing implements Agent {
        @Override
        public int doWork() throws IOException {
            if (failure != null) {
                for (RecorderRing ring : rings) {
                    ring.discard();
                }
                return 0;
            }
            return drainAll();
        }

        @Override
        public void onClose() {
            try {
                while (failure == null && drainAll() > 0) {
                    // every record handed over before the close is written
                }
            } catch (IOException | RuntimeException e) {
                failed(e);
            }
        }

        @Override
        public String roleName() {
            return ThreadNames.RECORDER; // off the tasks' per-release path
        }
    }

    private int drainAll() throws IOException {
        int written = 0;
        for (RecorderRing ring : rings) {
            written += ring.drain(sink, scratch);
        }
        return written;
    }

    /** A write failed: the writing ends; the first reason is kept. */
    private void failed(Throwable error) {
        if (failure == null) {
            failure = error.getMessage() == null ? error.toString() : error.getMessage();
        }
    }

    /**
     * Stops the thread after it has written everything handed over, and waits for it.
     *
     * @return why writing failed, or null
     */
    String stopAndJoin() {
        loop.close();
        return failure;
    }
}
