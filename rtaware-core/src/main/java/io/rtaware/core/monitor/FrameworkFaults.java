package io.rtaware.core.monitor;

import java.util.concurrent.atomic.AtomicLong;

/**
 * Counts the faults of a run's framework side and hands each to the one
 * {@link FrameworkErrorHandler} (see there for what counts). A handler that throws is itself
 * contained. Thread-safe.
 */
final class FrameworkFaults {

    private final FrameworkErrorHandler handler;
    private final AtomicLong count = new AtomicLong();

    FrameworkFaults(FrameworkErrorHandler handler) {
        this.handler = handler;
    }

    /**
     * @param source where it happened
     * @param error what was thrown
     */
    void report(String source, Throwable error) {
        count.incrementAndGet();
        try {
            handler.onError(source, error);
        } catch (Throwable ignored) {
            // The handler is the last resort: its own failure must not escape into a task thread.
        }
    }

    /**
     * A listener's fault, reported as "listener <i>class</i>.<i>event</i> on task '<i>task</i>'".
     *
     * @param listenerClass the listener's class name
     * @param event the listener method that threw
     * @param task the task whose event it was
     * @param error what was thrown
     */
    void reportListenerFault(String listenerClass, String event, String task, Throwable error) {
        report("listener " + listenerClass + "." + event + " on task '" + task + "'", error);
    }

    /** @return faults so far */
    long count() {
        return count.get();
    }
}
