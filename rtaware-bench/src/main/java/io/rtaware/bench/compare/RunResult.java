package io.rtaware.bench.compare;

import java.util.List;

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
 * @param rounds the same executor's numbers round by round (one measured segment each), in round
 *        order: what {@link PairedRounds} compares executors on; empty where no rounds were kept
 */
public record RunResult(String executor, Lateness latenessUs, long releases, long misses, long bursts,
                        double cpuUsPerRelease, double allocBytesPerRelease, List<Round> rounds) {

    /**
     * Copies the rounds: the row is a value.
     *
     * @param executor {@code rtaware}, {@code stpe} or {@code park-loop}
     * @param latenessUs release lateness against the intended release, microseconds
     * @param releases releases in the measurement windows
     * @param misses runs finished after release + period, plus skipped releases
     * @param bursts runs started less than half a period after the previous run of the same task
     * @param cpuUsPerRelease CPU time of the executor's threads (task threads plus its helpers) per release,
     *     microseconds; includes the task's work
     * @param allocBytesPerRelease bytes allocated on the executor's threads per release; the bench task
     *     allocates nothing, so this is the executor's (the framework's) own allocation
     * @param rounds the same executor's numbers round by round (one measured segment each), in round order:
     *     what {@link PairedRounds} compares executors on; empty where no rounds were kept
     */
    public RunResult {
        rounds = List.copyOf(rounds);
    }

    /**
     * A row without its rounds (a sweep's point, or a row made by hand).
     *
     * @param executor {@code rtaware}, {@code stpe} or {@code park-loop}
     * @param latenessUs release lateness against the intended release, microseconds
     * @param releases releases in the measurement windows
     * @param misses runs finished after release + period, plus skipped releases
     * @param bursts runs started less than half a period after the previous run of the same task
     * @param cpuUsPerRelease CPU time of the executor's threads (task threads plus its helpers) per release,
     *     microseconds; includes the task's work
     * @param allocBytesPerRelease bytes allocated on the executor's threads per release; the bench task
     *     allocates nothing, so this is the executor's (the framework's) own allocation
     */
    public RunResult(String executor, Lateness latenessUs, long releases, long misses, long bursts,
                     double cpuUsPerRelease, double allocBytesPerRelease) {
        this(executor, latenessUs, releases, misses, bursts, cpuUsPerRelease, allocBytesPerRelease, List.of());
    }

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

    /**
     * One round's measured segment of one executor.
     *
     * @param releases releases in the segment's window
     * @param misses misses among them (late runs plus skipped releases)
     * @param p999Us the segment's 99.9th percentile of lateness, microseconds
     */
    public record Round(long releases, long misses, double p999Us) {
    }
}
