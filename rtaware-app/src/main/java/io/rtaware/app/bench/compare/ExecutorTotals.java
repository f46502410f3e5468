package io.rtaware.app.bench.compare;

import io.rtaware.core.report.Rounding;
import org.HdrHistogram.Histogram;

/**
 * One executor's numbers summed over the measured segments: the tasks' {@link ReleaseStats}
 * merged after each segment, plus the CPU time and bytes allocated on the executor's threads
 * during the measurement windows. Not thread-safe: the coordinator owns it.
 */
final class ExecutorTotals {

    private final String executor;
    private final Histogram latenessNs =
            new Histogram(ReleaseStats.LOWEST_DISCERNIBLE_NS, ReleaseStats.HIGHEST_TRACKABLE_NS, 2);
    private long releases;
    private long misses;
    private long bursts;
    private long maxLatenessNs;
    private long cpuNs;
    private long allocBytes;

    ExecutorTotals(String executor) {
        this.executor = executor;
    }

    /** Adds one segment's per-task bookkeeping. */
    void add(ReleaseStats stats) {
        latenessNs.add(stats.latenessNs());
        releases += stats.releases();
        misses += stats.misses();
        bursts += stats.bursts();
        maxLatenessNs = Math.max(maxLatenessNs, stats.maxLatenessNs());
    }

    /** Adds the CPU time and allocation measured on the executor's threads in one window. */
    void addCost(long threadCpuNs, long threadAllocBytes) {
        cpuNs += threadCpuNs;
        allocBytes += threadAllocBytes;
    }

    /** @return the result row */
    RunResult result() {
        return new RunResult(executor,
                new RunResult.Lateness(us(percentile(50)), us(percentile(99)), us(percentile(99.9)), us(maxLatenessNs)),
                releases, misses, bursts,
                releases == 0 ? 0 : round1(cpuNs / 1e3 / releases),
                releases == 0 ? 0 : round1((double) allocBytes / releases));
    }

    private long percentile(double p) {
        // Buckets report their upper bound; no percentile exceeds the exact maximum.
        return latenessNs.getTotalCount() == 0 ? 0 : Math.min(latenessNs.getValueAtPercentile(p), maxLatenessNs);
    }

    private static double us(long ns) {
        return round1(ns / 1e3);
    }

    static double round1(double v) {
        return Rounding.toDecimals(v, 1);
    }
}
