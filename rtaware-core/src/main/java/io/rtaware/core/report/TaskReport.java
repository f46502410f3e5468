package io.rtaware.core.report;

/**
 * One task's timing over a run. Times are world time.
 *
 * @param name the task's name
 * @param schedule {@code periodic}, {@code continuous} or {@code once}
 * @param periodMs period in ms (null unless periodic)
 * @param deadlineMs relative deadline in ms (null unless periodic)
 * @param releases grid points at which the task was due (periodic: runs plus skipped)
 * @param runs cycles executed
 * @param misses releases whose run did not finish by the deadline, plus every skipped release
 * @param missPct {@code 100 * misses / releases}
 * @param skipped releases skipped because the task was still running
 * @param staleRuns cycles in which none of the task's inputs had new data
 * @param errors cycles that threw
 * @param expiredReads reads of an input older than its declared maximum age (one per input per cycle)
 * @param execUs execution time per cycle, microseconds
 * @param latenessUs start of the cycle minus its scheduled release, microseconds
 * @param listenerErrors faults of listeners (and the trace recorder) on this task's events,
 *     contained by the monitor: the task went on regardless
 */
public record TaskReport(String name, String schedule, Double periodMs, Double deadlineMs,
                         long releases, long runs, long misses, double missPct, long skipped,
                         long staleRuns, long errors, long expiredReads,
                         Percentiles execUs, Percentiles latenessUs, long listenerErrors) {

    /** A report without listener faults (for reports built outside a monitor). */
    public TaskReport(String name, String schedule, Double periodMs, Double deadlineMs, long releases, long runs,
                      long misses, double missPct, long skipped, long staleRuns, long errors, long expiredReads,
                      Percentiles execUs, Percentiles latenessUs) {
        this(name, schedule, periodMs, deadlineMs, releases, runs, misses, missPct, skipped, staleRuns, errors,
                expiredReads, execUs, latenessUs, 0);
    }
}
