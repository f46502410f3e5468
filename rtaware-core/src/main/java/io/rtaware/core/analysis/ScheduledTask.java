package io.rtaware.core.analysis;

/**
 * One periodic task as the schedulability analysis sees it: its period, relative deadline and
 * two execution times, in world nanoseconds. Immutable.
 *
 * @param name the task's name
 * @param periodNs period T, at least 1
 * @param deadlineNs relative deadline D, at least 1
 * @param execP99Ns the p99 execution time, the C of the analysis with p99
 * @param execMaxNs the largest execution time, the C of the analysis with max
 */
public record ScheduledTask(String name, long periodNs, long deadlineNs, long execP99Ns, long execMaxNs) {

    /**
     * @param name the task's name
     * @param periodNs period T, at least 1
     * @param deadlineNs relative deadline D, at least 1
     * @param execP99Ns the p99 execution time
     * @param execMaxNs the largest execution time
     * @throws IllegalArgumentException if a period or deadline is below 1 ns or an execution time negative
     */
    public ScheduledTask {
        if (periodNs < 1 || deadlineNs < 1) {
            throw new IllegalArgumentException("task '" + name + "': period and deadline must be at least 1 ns, got "
                    + periodNs + " and " + deadlineNs);
        }
        if (execP99Ns < 0 || execMaxNs < 0) {
            throw new IllegalArgumentException("task '" + name + "': execution times must not be negative");
        }
    }
}
