package io.rtaware.experiment.stats;

import java.util.Arrays;

/**
 * Count, mean, sample standard deviation (n - 1 in the denominator), minimum and maximum of a
 * sample. Values that are undefined for the sample's size are null: everything for an empty
 * sample, the standard deviation for a single value.
 *
 * @param n number of values
 * @param mean arithmetic mean, or null if {@code n == 0}
 * @param sd sample standard deviation, or null if {@code n < 2}
 * @param min smallest value, or null if {@code n == 0}
 * @param max largest value, or null if {@code n == 0}
 */
public record SampleStats(int n, Double mean, Double sd, Double min, Double max) {

    /**
     * @param values the sample; non-finite values are ignored
     * @return its statistics
     */
    public static SampleStats of(double[] values) {
        double[] v = Arrays.stream(values).filter(Double::isFinite).toArray();
        int n = v.length;
        if (n == 0) {
            return new SampleStats(0, null, null, null, null);
        }
        double mean = Arrays.stream(v).sum() / n;
        Double sd = null;
        if (n >= 2) {
            double ss = 0;
            for (double x : v) {
                ss += (x - mean) * (x - mean);
            }
            sd = Math.sqrt(ss / (n - 1));
        }
        return new SampleStats(n, mean, sd, Arrays.stream(v).min().getAsDouble(), Arrays.stream(v).max().getAsDouble());
    }
}
