package io.rtaware.app.bench.compare;

/**
 * One executor's row of the comparison, as written to the JSON ({@code runs[]}).
 *
 * @param executor {@code rtaware}, {@code stpe} or {@code park-loop}
 * @param latenessUs release lateness against the intended release, microseconds
 * @param releases releases in the measurement windows
 * @param misses runs finished after release + period, plus skipped releases
 * @param bursts runs started less than half a period after the previous run of the same task
 * @param cpuUsPerRelease CPU time of the executor's threads (task threads plus its helpers) per
 *        release, microseconds; includes the task's work
 * @param allocBytesPerRelease bytes allocated on the executor's threads per release; the bench
 *        task allocates nothing, so this is the executor's (the framework's) own allocation
 */
public record RunResult(String executor, Lateness latenessUs, long releases, long misses, long bursts,
                        double cpuUsPerRelease, double allocBytesPerRelease) {

    /**
     * Lateness percentiles in microseconds.
     *
     * @param p50 median
     * @param p99 99th percentile
     * @param p999 99.9th percentile
     * @param max exact largest value
     */
    public record Lateness(double p50, double p99, double p999, double max) {
    }
}
