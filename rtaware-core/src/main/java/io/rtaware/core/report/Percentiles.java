package io.rtaware.core.report;

import org.HdrHistogram.AbstractHistogram;

/**
 * Summary of a distribution in microseconds of world time.
 *
 * @param p50 median
 * @param p90 90th percentile
 * @param p99 99th percentile
 * @param max largest value recorded
 * @param mean arithmetic mean
 * @param p999 99.9th percentile (JSON key {@code p999}, after the older keys)
 */
public record Percentiles(double p50, double p90, double p99, double max, double mean, double p999) {

    /** All zeros: no samples. */
    public static final Percentiles EMPTY = new Percentiles(0, 0, 0, 0, 0, 0);

    /**
     * A summary known only to the 99th percentile (a fixture, or a document written before the
     * 99.9th was reported): the 99.9th is taken as unknown, 0.
     *
     * @param p50 median
     * @param p90 90th percentile
     * @param p99 99th percentile
     * @param max largest value
     * @param mean arithmetic mean
     */
    public Percentiles(double p50, double p90, double p99, double max, double mean) {
        this(p50, p90, p99, max, mean, 0);
    }

    /**
     * @param histogramNs a histogram of nanosecond values
     * @param exactMaxNs the exact maximum (a histogram rounds and clamps)
     * @param exactSumNs the exact sum, for the mean
     * @return the summary in microseconds, rounded to 0.1 us
     */
    public static Percentiles ofNanos(AbstractHistogram histogramNs, long exactMaxNs, double exactSumNs) {
        long n = histogramNs.getTotalCount();
        if (n == 0) {
            return EMPTY;
        }
        // Histogram buckets report their upper bound; no percentile can exceed the exact maximum.
        return new Percentiles(us(Math.min(histogramNs.getValueAtPercentile(50), exactMaxNs)),
                us(Math.min(histogramNs.getValueAtPercentile(90), exactMaxNs)),
                us(Math.min(histogramNs.getValueAtPercentile(99), exactMaxNs)), us(exactMaxNs), us(exactSumNs / n),
                us(Math.min(histogramNs.getValueAtPercentile(99.9), exactMaxNs)));
    }

    private static double us(double ns) {
        return Math.round(ns / 100.0) / 10.0;
    }
}
