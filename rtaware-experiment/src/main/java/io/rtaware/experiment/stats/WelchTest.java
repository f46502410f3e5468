package io.rtaware.experiment.stats;

import java.util.Arrays;
import org.apache.commons.math3.distribution.TDistribution;
import org.apache.commons.math3.stat.StatUtils;
import org.apache.commons.math3.stat.inference.TTest;

/**
 * Welch's two-sided t-test of two independent samples with possibly unequal variances: the
 * statistic t, the Welch–Satterthwaite degrees of freedom, the two-sided p-value from Apache
 * Commons Math ({@link TTest}, which uses the same degrees of freedom), and the "confidence"
 * {@code 1 - p} that the paper quotes. When the test is undefined the numbers are null and
 * {@code note} says why.
 *
 * @param t Welch's t statistic (mean of a minus mean of b over the standard error), or null
 * @param df Welch–Satterthwaite degrees of freedom, or null
 * @param p two-sided p-value, or null
 * @param confidence {@code 1 - p}, or null
 * @param note null when the test was computed, else the reason it is n/a
 * @param detectableDifference the test's power as a size: the smallest difference of the means
 *     it detects at {@link #ALPHA} with probability {@link #POWER}, given the observed spreads and
 *     sizes, {@code (t(1 - alpha/2, df) + t(power, df)) * sqrt(va/na + vb/nb)}; null when n/a
 */
public record WelchTest(Double t, Double df, Double p, Double confidence, String note, Double detectableDifference) {

    /** Significance level of the detectable difference. */
    public static final double ALPHA = 0.05;
    /** Probability of detecting a difference of {@link #detectableDifference()} (the usual 80 %). */
    public static final double POWER = 0.8;

    /**
     * A test without its detectable difference.
     *
     * @param t the statistic, or null
     * @param df degrees of freedom, or null
     * @param p p-value, or null
     * @param confidence 1 - p, or null
     * @param note null, or why n/a
     */
    public WelchTest(Double t, Double df, Double p, Double confidence, String note) {
        this(t, df, p, confidence, note, null);
    }

    /**
     * @param a the first sample (non-finite values ignored)
     * @param b the second sample (non-finite values ignored)
     * @return the test, or an n/a result with the reason
     */
    public static WelchTest of(double[] a, double[] b) {
        double[] x = Arrays.stream(a).filter(Double::isFinite).toArray();
        double[] y = Arrays.stream(b).filter(Double::isFinite).toArray();
        if (x.length < 2 || y.length < 2) {
            return notApplicable("needs at least 2 values in each sample, have " + x.length + " and " + y.length);
        }
        double vx = StatUtils.variance(x);
        double vy = StatUtils.variance(y);
        if (vx == 0 && vy == 0) {
            return notApplicable("no variance in either sample (all values equal within each)");
        }
        TTest test = new TTest();
        double t = test.t(x, y);
        double p = test.tTest(x, y);
        double df = welchSatterthwaite(vx, x.length, vy, y.length);
        return new WelchTest(t, df, p, 1 - p, null, detectable(vx, x.length, vy, y.length));
    }

    /**
     * @param reason why the test cannot be computed
     * @return a result with no numbers
     */
    public static WelchTest notApplicable(String reason) {
        return new WelchTest(null, null, null, null, reason);
    }

    /**
     * @param v1 variance of the first sample
     * @param n1 its size
     * @param v2 variance of the second sample
     * @param n2 its size
     * @return the Welch–Satterthwaite approximation of the degrees of freedom
     */
    static double welchSatterthwaite(double v1, int n1, double v2, int n2) {
        double a = v1 / n1;
        double b = v2 / n2;
        return (a + b) * (a + b) / (a * a / (n1 - 1) + b * b / (n2 - 1));
    }

    /**
     * @param v1 variance of the first sample
     * @param n1 its size
     * @param v2 variance of the second sample
     * @param n2 its size
     * @return the smallest difference of the means detected at {@link #ALPHA} with probability {@link #POWER}
     */
    static double detectable(double v1, int n1, double v2, int n2) {
        double df = welchSatterthwaite(v1, n1, v2, n2);
        TDistribution dist = new TDistribution(df);
        return (dist.inverseCumulativeProbability(1 - ALPHA / 2) + dist.inverseCumulativeProbability(POWER))
                * Math.sqrt(v1 / n1 + v2 / n2);
    }

    /** @return true if the numbers were computed */
    public boolean applicable() {
        return note == null;
    }
}
