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
     * {@code release + deadlineNs}.
     *
     * @param periodNs period in world nanoseconds
     * @param offsetNs first release after the monitor's start, in world nanoseconds
     * @param deadlineNs relative deadline, at most the period
     */
    record Periodic(long periodNs, long offsetNs, long deadlineNs) implements Schedule {
        @Override
        public String kind() {
            return "periodic";
        }

        /**
         * @param newPeriodNs another period
         * @return this schedule with another period, its deadline scaled by the same factor
         */
        public Periodic withPeriod(long newPeriodNs) {
            long newDeadline = deadlineNs == periodNs ? newPeriodNs
                    : Math.max(1, Math.round((double) deadlineNs * newPeriodNs / periodNs));
            return new Periodic(newPeriodNs, offsetNs, newDeadline);
        }

        @Override
        public String toString() {
            return "periodic(" + Durations.format(periodNs)
                    + (offsetNs != 0 ? ", offset " + Durations.format(offsetNs) : "")
                    + (deadlineNs != periodNs ? ", deadline " + Durations.format(deadlineNs) : "") + ")";
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

    /** @return a continuous schedule */
    static Continuous continuous() {
        return new Continuous();
    }

    /** @return a schedule that runs once, at start */
    static Once once() {
        return new Once(0);
    }
}
