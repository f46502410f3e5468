package io.rtaware.core.conditions;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.OptionalLong;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The timer slack the kernel gives the threads that run cycles, as each thread reads it from
 * {@code /proc} once it is set up. Linux lets a timer of a normally scheduled thread fire up to
 * its slack late (50 000 ns by default) so that wake-ups can be batched; a real-time framework's
 * threads ask for 1 ns (the {@code rtaware-rt} module's {@code io.rtaware.rt.MinimalTimerSlack}).
 * This records what they got, whoever set it: the largest and smallest slack of the threads
 * observed, reported in the conditions as {@code timer_slack_ns}.
 *
 * <p>Thread-safe. Reading allocates; call it at a thread's start, not in its cycles.
 */
public final class ThreadTimerSlack {

    private static final long UNKNOWN = -1;

    private final Path proc;
    private final AtomicLong largestNs = new AtomicLong(UNKNOWN);
    private final AtomicLong smallestNs = new AtomicLong(Long.MAX_VALUE);
    private final AtomicLong threads = new AtomicLong();

    /**
     * @param proc the proc file system ({@code /proc}; another folder in tests)
     */
    public ThreadTimerSlack(Path proc) {
        this.proc = proc;
    }

    /** @return an observer of this machine's {@code /proc} */
    public static ThreadTimerSlack ofThisMachine() {
        return new ThreadTimerSlack(Path.of("/proc"));
    }

    /**
     * Reads the calling thread's timer slack ({@code /proc/thread-self} names the thread as
     * {@code PID/task/TID}; the slack is in {@code /proc/TID/timerslack_ns}, Linux 4.6 and
     * later) and counts it. Nothing is counted where the files do not exist.
     *
     * @return the slack in ns, or empty where it cannot be read
     */
    public OptionalLong observeCurrentThread() {
        OptionalLong slack = readCurrentThread();
        if (slack.isPresent()) {
            long ns = slack.getAsLong();
            largestNs.accumulateAndGet(ns, Math::max);
            smallestNs.accumulateAndGet(ns, Math::min);
            threads.incrementAndGet();
        }
        return slack;
    }

    private OptionalLong readCurrentThread() {
        try {
            Path self = Files.readSymbolicLink(proc.resolve("thread-self"));
            String tid = self.getFileName().toString();
            String text = Files.readString(proc.resolve(tid).resolve("timerslack_ns")).trim();
            long ns = Long.parseLong(text);
            return ns < 0 ? OptionalLong.empty() : OptionalLong.of(ns);
        } catch (IOException | NumberFormatException | UnsupportedOperationException | SecurityException e) {
            return OptionalLong.empty();
        }
    }

    /** @return the largest slack of the threads observed, or empty if none could be read */
    public OptionalLong largestNs() {
        long ns = largestNs.get();
        return ns == UNKNOWN ? OptionalLong.empty() : OptionalLong.of(ns);
    }

    /** @return the smallest slack of the threads observed, or empty if none could be read */
    public OptionalLong smallestNs() {
        return threads.get() == 0 ? OptionalLong.empty() : OptionalLong.of(smallestNs.get());
    }

    /** @return how many threads were observed */
    public long threads() {
        return threads.get();
    }
}
