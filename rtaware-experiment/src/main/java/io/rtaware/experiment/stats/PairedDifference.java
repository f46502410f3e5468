package io.rtaware.experiment.stats;

import java.util.Arrays;
import org.apache.commons.math3.distribution.TDistribution;

/**
 * The mean of paired differences {@code a[i] - b[i]} (two sets run with the same seed i) with its
 * two-sided t interval at {@link #CONFIDENCE}.
 *
 * @param n pairs
 * @param mean the mean difference
 * @param lower the interval's lower bound, or NaN with fewer than 2 pairs
 * @param upper its upper bound, or NaN with fewer than 2 pairs
 */
public record PairedDifference(int n, double mean, double lower, double upper) {

    /** The interval's confidence level. */
    public static final double CONFIDENCE = 0.95;

    /**
     * @param a the first value of each pair
     * @param b the second, in the same order
     * @return the mean difference a - b and its interval
     */
    public static PairedDifference of(double[] a, double[] b) {
        if (a.length != b.length || a.length == 0) {
            throw new IllegalArgumentException("paired samples need the same, non-zero length, got " + a.length + " and "
                    + b.length);
        }
        int n = a.length;
        double[] d = new double[n];
        Arrays.setAll(d, i -> a[i] - b[i]);
        double mean = Arrays.stream(d).average().orElseThrow();
        if (n < 2) {
            return new PairedDifference(n, mean, Double.NaN, Double.NaN);
        }
        double ss = Arrays.stream(d).map(x -> (x - mean) * (x - mean)).sum();
        double half = new TDistribution(n - 1).inverseCumulativeProbability(1 - (1 - CONFIDENCE) / 2)
                * Math.sqrt(ss / (n - 1) / n);
        return new PairedDifference(n, mean, mean - half, mean + half);
    }
}
