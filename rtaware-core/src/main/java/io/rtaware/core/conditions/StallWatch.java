package io.rtaware.core.conditions;

import io.rtaware.core.agent.AgentThread;
import java.util.Objects;
import java.util.concurrent.locks.LockSupport;
import java.util.function.LongConsumer;
import java.util.function.LongSupplier;
import org.agrona.concurrent.Agent;
import org.agrona.concurrent.NoOpIdleStrategy;

/**
 * Sees a stop of the whole process in the process's own clock: one thread asks to sleep
 * {@value #INTERVAL_MS} ms at a time and keeps the longest it woke later than asked. A
 * {@code SIGSTOP}, a frozen virtual machine or a swap storm stops every thread of the process,
 * which no CPU counter shows (the machine looks idle) and no JVM event reports; this thread
 * wakes as late as the stop was long. A busy machine or a JVM pause delays it too, as they delay
 * the tasks. Costs one wake-up every {@value #INTERVAL_MS} ms, allocating nothing.
 */
final class StallWatch implements AutoCloseable {

    /** How long the watcher sleeps at a time, ms. */
    static final long INTERVAL_MS = 20;

    private final Watcher watcher;
    private final AgentThread thread;

    private StallWatch(Watcher watcher) {
        this.watcher = watcher;
        // Not named rtaware-*: bench's allocation check counts those threads as the framework's.
        this.thread = AgentThread.start(watcher, NoOpIdleStrategy.INSTANCE, error -> { });
    }

    /** @return a watcher of this process, running until closed */
    static StallWatch start() {
        return new StallWatch(new Watcher(System::nanoTime, LockSupport::parkNanos));
    }

    /** @return the longest the watcher woke later than it asked so far, ms */
    double longestStallMs() {
        return watcher.longestLateNs() / 1e6;
    }

    @Override
    public void close() {
        thread.close();
    }

    /** The watcher's loop: sleep, then keep how late it woke. Its clock and sleep are given, for tests. */
    static final class Watcher implements Agent {
        private final LongSupplier nanoTime;
        private final LongConsumer sleep;
        private volatile long longestLateNs;

        /**
         * @param nanoTime the process's monotonic clock
         * @param sleep sleeps about the nanoseconds given (may return early)
         */
        Watcher(LongSupplier nanoTime, LongConsumer sleep) {
            this.nanoTime = Objects.requireNonNull(nanoTime, "nanoTime");
            this.sleep = Objects.requireNonNull(sleep, "sleep");
        }

        @Override
        public int doWork() {
            long asked = INTERVAL_MS * 1_000_000L;
            long before = nanoTime.getAsLong();
            sleep.accept(asked);
            long late = nanoTime.getAsLong() - before - asked;
            if (late > longestLateNs) {
                longestLateNs = late;
            }
            return 0;
        }

        long longestLateNs() {
            return longestLateNs;
        }

        @Override
        public String roleName() {
            return "conditions-stall-watch";
        }
    }
}
