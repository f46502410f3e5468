package io.rtaware.bench.compare;

import io.rtaware.core.report.Rounding;
import java.util.ArrayList;
import java.util.List;
import org.HdrHistogram.Histogram;

/**
 * One executor's numbers summed over the measured segments: the tasks' {@link ReleaseStats}
 * merged after each segment, plus the CPU time and bytes allocated on the executor's threads
 * during the measurement windows, and the same numbers round by round ({@link RunResult#rounds()}).
 * Not thread-safe: the coordinator owns it.
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
    /** The current round's lateness, reset at each {@link #endRound()}. */
    private final Histogram roundLatenessNs =
            new Histogram(ReleaseStats.LOWEST_DISCERNIBLE_NS, ReleaseStats.HIGHEST_TRACKABLE_NS, 2);
    private long roundReleases;
    private long roundMisses;
    private long roundMaxLatenessNs;
    private final List<RunResult.Round> rounds = new ArrayList<>();

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
        roundLatenessNs.add(stats.latenessNs());
        roundReleases += stats.releases();
        roundMisses += stats.misses();
        roundMaxLatenessNs = Math.max(roundMaxLatenessNs, stats.maxLatenessNs());
    }

    /** Closes the round whose segment was just added (every task's stats), keeping its numbers. */
    void endRound() {
        rounds.add(new RunResult.Round(roundReleases, roundMisses,
                us(percentile(roundLatenessNs, 99.9, roundMaxLatenessNs))));
        roundLatenessNs.reset();
        roundReleases = 0;
        roundMisses = 0;
        roundMaxLatenessNs = 0;
    }

    /** Adds the CPU time and allocation measured on the executor's threads in one window. */
    void addCost(long threadCpuNs, long threadAllocBytes) {
        cpuNs += threadCpuNs;
        allocBytes += threadAllocBytes;
    }

    /** @return the result row */
    RunResult result() {
        return new RunResult(executor,
                new RunResult.Lateness(us(percentile(latenessNs, 50, maxLatenessNs)),
                        us(percentile(latenessNs, 99, maxLatenessNs)), us(percentile(latenessNs, 99.9, maxLatenessNs)),
                        us(maxLatenessNs)),
                releases, misses, bursts,
                releases == 0 ? 0 : round1(cpuNs / 1e3 / releases),
                releases == 0 ? 0 : round1((double) allocBytes / releases), rounds);
    }

    private static long percentile(Histogram histogram, double p, long maxNs) {
        // Buckets report their upper bound; no percentile exceeds the exact maximum.
        return histogram.getTotalCount() == 0 ? 0 : Math.min(histogram.getValueAtPercentile(p), maxNs);
    }

    private static double us(long ns) {
        return round1(ns / 1e3);
    }

    static double round1(double v) {
        return Rounding.toDecimals(v, 1);
    }
}
