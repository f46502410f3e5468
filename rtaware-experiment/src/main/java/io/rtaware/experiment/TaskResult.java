package io.rtaware.experiment;

/**
 * One behavior's timing in one run, as read from the run's {@code report.json}.
 *
 * @param releases grid points at which the task was due
 * @param misses releases that missed their deadline (including skipped ones)
 * @param missPct {@code 100 * misses / releases}
 * @param staleRuns cycles that ran with no new input
 * @param execP99Us 99th percentile of the execution time per cycle, microseconds (world time)
 * @param skipped releases skipped because the task was still running (counted in misses too),
 *     or null when the results predate the column
 * @param maxSafePeriodMs the largest safe period the run's advice gave the task by the reaction
 *     rule (top speed x (period + input age p99) + stopping distance within the safety range), or
 *     null when the task declares no reaction or the report has no such advice
 */
public record TaskResult(long releases, long misses, double missPct, long staleRuns, double execP99Us, Long skipped,
                         Double maxSafePeriodMs) {

    /**
     * A result without the reaction rule's bound.
     *
     * @param releases grid points at which the task was due
     * @param misses releases that missed their deadline
     * @param missPct {@code 100 * misses / releases}
     * @param staleRuns cycles that ran with no new input
     * @param execP99Us p99 execution time, µs
     * @param skipped skipped releases, or null
     */
    public TaskResult(long releases, long misses, double missPct, long staleRuns, double execP99Us, Long skipped) {
        this(releases, misses, missPct, staleRuns, execP99Us, skipped, null);
    }

    /**
     * A result without the skipped count.
     *
     * @param releases grid points at which the task was due
     * @param misses releases that missed their deadline
     * @param missPct {@code 100 * misses / releases}
     * @param staleRuns cycles that ran with no new input
     * @param execP99Us p99 execution time, µs
     */
    public TaskResult(long releases, long misses, double missPct, long staleRuns, double execP99Us) {
        this(releases, misses, missPct, staleRuns, execP99Us, null, null);
    }
}
