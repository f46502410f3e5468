package io.rtaware.core.time;

/**
 * Puts the calling thread to sleep until an absolute instant of {@link System#nanoTime()}'s clock
 * ({@code CLOCK_MONOTONIC} on Linux), in one call to the operating system where it can: the way
 * cyclictest waits ({@code clock_nanosleep} with {@code TIMER_ABSTIME}). The JVM's own
 * {@link java.util.concurrent.locks.LockSupport#parkNanos} sleeps on a condition variable
 * instead: a futex wait and, on every wake-up, a futex wake to release the mutex the condition
 * variable hands back marked as contended (glibc), about a fifth of a sleeping task thread's CPU
 * time in issue 16's profile of 1000 tasks at 100 Hz.
 *
 * <p>A thread sleeping here cannot be woken early by {@code LockSupport.unpark}: the monitor uses
 * it only for task threads of the threaded executor, which nothing wakes but their release time,
 * and never sleeps longer than 100 ms in one call, so a stop is noticed within that.
 *
 * <p>Implementations are thread-safe and allocate nothing per call.
 */
@FunctionalInterface
public interface MonotonicSleeper {

    /**
     * Sleeps until {@code System.nanoTime()} reaches {@code nanoTime}. May return earlier (a
     * signal): callers check the time again.
     *
     * @param nanoTime the instant to wake at, on {@link System#nanoTime()}'s clock
     */
    void sleepUntil(long nanoTime);
}
