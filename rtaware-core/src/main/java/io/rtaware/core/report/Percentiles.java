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
     * Each percentile is the upper bound of the histogram bucket it falls into, and never above
     * the exact maximum. A recorder that clamps values above the histogram's range into its top
     * bucket keeps the exact maximum as that bucket's upper bound: a percentile there reads as the
     * maximum.
     *
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
        return new Percentiles(us(atPercentile(histogramNs, 50, exactMaxNs)),
                us(atPercentile(histogramNs, 90, exactMaxNs)),
                us(atPercentile(histogramNs, 99, exactMaxNs)), us(exactMaxNs), us(exactSumNs / n),
                us(atPercentile(histogramNs, 99.9, exactMaxNs)));
    }

    private static long atPercentile(AbstractHistogram histogramNs, double percentile, long exactMaxNs) {
        long valueNs = histogramNs.getValueAtPercentile(percentile);
        boolean topBucket = valueNs >= histogramNs.lowestEquivalentValue(histogramNs.getHighestTrackableValue());
        return topBucket ? exactMaxNs : Math.min(valueNs, exactMaxNs);
    }

    private static double us(double ns) {
        return Math.round(ns / 100.0) / 10.0;
    }
}
