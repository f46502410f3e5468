package io.rtaware.experiment;

/**
 * One behavior's timing in one run, as read from the run's {@code report.json}.
 *
 * @param releases grid points at which the task was due
 * @param misses releases that missed their deadline (including skipped ones)
 * @param missPct {@code 100 * misses / releases}
 * @param staleRuns cycles that ran with no new input
 * @param execP99Us 99th percentile of the execution time per cycle, microseconds (world time)
 */
public record TaskResult(long releases, long misses, double missPct, long staleRuns, double execP99Us) {
}
