package io.rtaware.core.task;

import io.rtaware.core.time.Durations;
import java.time.Duration;

/**
 * When a task runs: periodically on an absolute grid, continuously, or once.
 *
 * <p>Validation is deferred to the monitor, which reports every bad schedule together with
 * every other configuration error before anything runs.
 */
public sealed interface Schedule permits Schedule.Periodic, Schedule.Continuous, Schedule.Once {

    /**
     * Release k is at {@code start + offsetNs + k * periodNs}; each release must finish by
     * {@code release + deadlineNs}. A periodic schedule may declare a period range
     * ({@link #isAdaptive()}): with adaptive periods enabled on the monitor, the period then moves
     * inside {@code [minPeriodNs, maxPeriodNs]} from run-time evidence, starting at
     * {@code periodNs}; otherwise it stays at {@code periodNs}.
     *
     * @param periodNs period in world nanoseconds (the initial period, if adaptive)
     * @param offsetNs first release after the monitor's start, in world nanoseconds
     * @param deadlineNs relative deadline, at most the period
     * @param minPeriodNs shortest period the monitor may choose ({@code periodNs} if fixed)
     * @param maxPeriodNs longest period the monitor may choose ({@code periodNs} if fixed)
     */
    record Periodic(long periodNs, long offsetNs, long deadlineNs, long minPeriodNs, long maxPeriodNs)
            implements Schedule {

        /**
         * A fixed period.
         *
         * @param periodNs period in world nanoseconds
         * @param offsetNs first release after the monitor's start
         * @param deadlineNs relative deadline, at most the period
         */
        public Periodic(long periodNs, long offsetNs, long deadlineNs) {
            this(periodNs, offsetNs, deadlineNs, periodNs, periodNs);
        }

        @Override
        public String kind() {
            return "periodic";
        }

        /** @return true if a period range was declared */
        public boolean isAdaptive() {
            return minPeriodNs != maxPeriodNs;
        }

        /**
         * @param newPeriodNs another period
         * @return this schedule with another period, its deadline scaled by the same factor; a
         *     fixed schedule stays fixed (at the new period), an adaptive one keeps its range
         */
        public Periodic withPeriod(long newPeriodNs) {
            long newDeadline = deadlineNs == periodNs ? newPeriodNs
                    : Math.max(1, Math.round((double) deadlineNs * newPeriodNs / periodNs));
            return isAdaptive() ? new Periodic(newPeriodNs, offsetNs, newDeadline, minPeriodNs, maxPeriodNs)
                    : new Periodic(newPeriodNs, offsetNs, newDeadline);
        }

        @Override
        public String toString() {
            return "periodic(" + Durations.format(periodNs)
                    + (offsetNs != 0 ? ", offset " + Durations.format(offsetNs) : "")
                    + (deadlineNs != periodNs ? ", deadline " + Durations.format(deadlineNs) : "")
                    + (isAdaptive() ? ", adaptive " + Durations.format(minPeriodNs) + ".."
                            + Durations.format(maxPeriodNs) : "") + ")";
        }
    }

    /** Runs again as soon as it returns, e.g. a task driven by a socket. No deadline. */
    record Continuous() implements Schedule {
        @Override
        public String kind() {
            return "continuous";
        }

        @Override
        public String toString() {
            return "continuous";
        }
    }

    /**
     * Runs once.
     *
     * @param offsetNs when to run, after the monitor's start
     */
    record Once(long offsetNs) implements Schedule {
        @Override
        public String kind() {
            return "once";
        }

        @Override
        public String toString() {
            return offsetNs == 0 ? "once" : "once(offset " + Durations.format(offsetNs) + ")";
        }
    }

    /** @return {@code periodic}, {@code continuous} or {@code once}, as in the report */
    String kind();

    /**
     * @param period the period; the deadline is the period
     * @return a periodic schedule with no offset
     */
    static Periodic periodic(Duration period) {
        return periodic(period.toNanos());
    }

    /**
     * @param periodNs the period in nanoseconds; the deadline is the period
     * @return a periodic schedule with no offset
     */
    static Periodic periodic(long periodNs) {
        return new Periodic(periodNs, 0, periodNs);
    }

    /**
     * @param period the period
     * @param offset the first release after start
     * @param deadline the relative deadline, at most the period
     * @return a periodic schedule
     */
    static Periodic periodic(Duration period, Duration offset, Duration deadline) {
        return new Periodic(period.toNanos(), offset.toNanos(), deadline.toNanos());
    }

    /**
     * A periodic schedule with a period range, starting at the shortest period; the deadline is
     * the period. The period moves only when the monitor runs with adaptive periods enabled.
     *
     * @param min shortest period
     * @param max longest period
     * @return an adaptive periodic schedule
     */
    static Periodic adaptive(Duration min, Duration max) {
        return adaptive(min, min, max);
    }

    /**
     * A periodic schedule with a period range; the deadline is the period.
     *
     * @param initial the period to start with, within the range
     * @param min shortest period
     * @param max longest period
     * @return an adaptive periodic schedule
     */
    static Periodic adaptive(Duration initial, Duration min, Duration max) {
        return new Periodic(initial.toNanos(), 0, initial.toNanos(), min.toNanos(), max.toNanos());
    }

    /** @return a continuous schedule */
    static Continuous continuous() {
        return new Continuous();
    }

    /** @return a schedule that runs once, at start */
    static Once once() {
        return new Once(0);
    }
}
