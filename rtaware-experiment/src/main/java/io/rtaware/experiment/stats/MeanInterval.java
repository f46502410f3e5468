package io.rtaware.experiment.stats;

import org.apache.commons.math3.distribution.FDistribution;
import org.apache.commons.math3.distribution.TDistribution;

/**
 * Two-sided intervals at {@link #CONFIDENCE} comparing two independent samples from their
 * summaries: the difference of the means (Welch, unequal variances) and the ratio of the
 * variances (F).
 *
 * @param estimate the point estimate
 * @param lower the lower bound
 * @param upper the upper bound
 */
public record MeanInterval(double estimate, double lower, double upper) {

    /** The intervals' confidence level. */
    public static final double CONFIDENCE = 0.95;

    /**
     * @param a a sample's statistics, at least 2 values
     * @param b another's, at least 2 values
     * @return mean of a minus mean of b, with Welch's interval
     */
    public static MeanInterval meanDifference(SampleStats a, SampleStats b) {
        check(a, b);
        double va = a.sd() * a.sd() / a.n();
        double vb = b.sd() * b.sd() / b.n();
        double diff = a.mean() - b.mean();
        if (va + vb == 0) {
            return new MeanInterval(diff, diff, diff);
        }
        double df = WelchTest.welchSatterthwaite(a.sd() * a.sd(), a.n(), b.sd() * b.sd(), b.n());
        double half = new TDistribution(df).inverseCumulativeProbability(1 - (1 - CONFIDENCE) / 2) * Math.sqrt(va + vb);
        return new MeanInterval(diff, diff - half, diff + half);
    }

    /**
     * @param a a sample's statistics, at least 2 values, not all equal
     * @param b another's, at least 2 values, not all equal
     * @return the variance of a over that of b, with the F interval
     */
    public static MeanInterval varianceRatio(SampleStats a, SampleStats b) {
        check(a, b);
        double ratio = a.sd() * a.sd() / (b.sd() * b.sd());
        FDistribution f = new FDistribution(a.n() - 1, b.n() - 1);
        return new MeanInterval(ratio, ratio / f.inverseCumulativeProbability(1 - (1 - CONFIDENCE) / 2),
                ratio / f.inverseCumulativeProbability((1 - CONFIDENCE) / 2));
    }

    private static void check(SampleStats a, SampleStats b) {
        if (a.sd() == null || b.sd() == null) {
            throw new IllegalArgumentException("an interval needs at least 2 values in each sample, have " + a.n()
                    + " and " + b.n());
        }
    }
}
