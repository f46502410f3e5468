package io.rtaware.core.time;

import java.util.Arrays;
import java.util.Objects;

/**
 * A clock that only moves when a test moves it, for exact tests of timing rules.
 *
 * <p>A task under test simulates its execution time by calling {@link #advance(long)} from
 * inside its cycle; observers registered with {@link #onAdvance(AdvanceObserver)} (the step
 * executor's deadline watchdog) see every advance at once, so a deadline miss is reported at
 * the deadline, while the task is still inside its cycle, exactly as on real threads.
 *
 * <p>Thread-safe for reading; advancing is meant for one thread (the test's).
 */
public final class ManualClock implements Clock {

    /** Told about every advance of the clock. */
    @FunctionalInterface
    public interface AdvanceObserver {
        /**
         * @param fromNs world time before the advance
         * @param toNs world time after the advance
         */
        void advanced(long fromNs, long toNs);
    }

    private volatile long nowNs;
    /** Copy-on-write array: advancing iterates it without allocating. */
    private volatile AdvanceObserver[] observers = new AdvanceObserver[0];

    /** Starts at world time zero. */
    public ManualClock() {
        this(0L);
    }

    /** @param startNs the initial world time in nanoseconds */
    public ManualClock(long startNs) {
        this.nowNs = startNs;
    }

    @Override
    public long nanos() {
        return nowNs;
    }

    /**
     * Moves time forward and tells every observer.
     *
     * @param deltaNs how far to move, in nanoseconds; must not be negative
     */
    public void advance(long deltaNs) {
        if (deltaNs < 0) {
            throw new IllegalArgumentException("a clock cannot go back: delta " + deltaNs + " ns");
        }
        long from = nowNs;
        long to = from + deltaNs;
        nowNs = to;
        for (AdvanceObserver observer : observers) {
            observer.advanced(from, to);
        }
    }

    /**
     * Moves time forward to an absolute world time (no-op if it is already there or later).
     *
     * @param targetNs the world time to reach
     */
    public void advanceTo(long targetNs) {
        if (targetNs > nowNs) {
            advance(targetNs - nowNs);
        }
    }

    /**
     * @param observer told about every later advance
     * @return a handle that removes the observer when run
     */
    public Runnable onAdvance(AdvanceObserver observer) {
        Objects.requireNonNull(observer, "observer");
        synchronized (this) {
            AdvanceObserver[] grown = Arrays.copyOf(observers, observers.length + 1);
            grown[grown.length - 1] = observer;
            observers = grown;
        }
        return () -> {
            synchronized (this) {
                observers = Arrays.stream(observers).filter(o -> o != observer).toArray(AdvanceObserver[]::new);
            }
        };
    }
}
