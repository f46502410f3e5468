package io.rtaware.core.conditions;

import java.util.List;

/**
 * What the JVM says about itself: who built it, how it was started, its collectors and heap,
 * and its pauses over a span of time. {@link PlatformJvmProbe} asks the platform's management
 * beans and its safepoint log; tests give a fake.
 */
public interface JvmProbe {

    /** @return the JVM's vendor, e.g. {@code Debian} */
    String vendor();

    /** @return the JVM's version, e.g. {@code 17.0.15+6-Debian-1deb12u1} */
    String version();

    /** @return the JVM's options as given at its start (e.g. {@code -XX:+UseZGC}) */
    List<String> options();

    /** @return the names of the JVM's collectors (its garbage collector beans), e.g. {@code ZGC Pauses} */
    List<String> collectors();

    /** @return the largest heap the JVM may use, bytes, or -1 if it does not say */
    long heapMaxBytes();

    /**
     * Starts counting the JVM's stop-the-world pauses: collections and, where the JVM exposes
     * it, the time threads took to reach a safepoint.
     *
     * @return the counter, to read at the end and close
     */
    PauseWatch watchPauses();

    /**
     * The JVM's pauses since {@link #watchPauses()}; closing it stops the counting, after which
     * the figures stay readable.
     */
    interface PauseWatch extends AutoCloseable {

        /**
         * @return the collectors' pauses that stopped the application threads (one collection
         *     may pause more than once: ZGC's three times)
         */
        long gcCount();

        /** @return their summed duration, ms */
        double gcTotalMs();

        /** @return the longest of them, ms (0 if none) */
        double gcMaxPauseMs();

        /**
         * @param ms a duration, ms
         * @return the stops longer than it: each collection's longest pause and each safepoint's
         *     time to reach (the time the first stopped threads waited for the last)
         */
        long stopsLongerThan(double ms);

        /** @return safepoints seen (each a stop of every application thread), or -1 where not measured */
        long safepoints();

        /** @return the longest time to reach a safepoint, ms, or null where it is not measured */
        Double maxTimeToSafepointMs();

        /** @return null when the time to safepoint is measured, else why it is not */
        String safepointNote();

        /**
         * @return the longest the whole process was stopped, ms, as a thread of its own that
         *     sleeps {@value StallWatch#INTERVAL_MS} ms at a time saw it (how much later than
         *     asked it woke: a {@code SIGSTOP}, a frozen VM, a swap storm, and also a JVM pause or
         *     a busy machine); NaN where not measured
         */
        double longestStallMs();

        /** Stops the counting; idempotent. */
        @Override
        void close();
    }
}
