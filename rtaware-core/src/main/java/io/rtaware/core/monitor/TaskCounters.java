package io.rtaware.core.monitor;

/**
 * A task's counters at one moment (see {@link io.rtaware.core.report.TaskReport} for meanings).
 *
 * @param releases releases so far
 * @param runs cycles run
 * @param misses deadline misses including skipped releases
 * @param skipped skipped releases
 * @param staleRuns cycles without new input data
 * @param errors cycles that threw
 * @param expiredReads reads of inputs older than their declared maximum age
 * @param recentExecP99Ns 99th percentile (exact, in ns) of the execution times of the latest
 *     {@value #RECENT_EXEC_RUNS} runs (of all runs before that many have run): of n values sorted,
 *     the ceil(0.99 n)-th, so the third largest of 256; 0 before the first run. A live figure for
 *     observers; the report's percentiles cover the whole run
 */
public record TaskCounters(long releases, long runs, long misses, long skipped, long staleRuns,
                           long errors, long expiredReads, long recentExecP99Ns) {

    /** How many of the latest runs {@link #recentExecP99Ns()} covers. */
    public static final int RECENT_EXEC_RUNS = CycleStatistics.RECENT_EXEC_CYCLES;
}
