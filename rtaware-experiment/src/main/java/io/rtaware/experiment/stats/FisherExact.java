package io.rtaware.experiment.stats;

import org.apache.commons.math3.distribution.HypergeometricDistribution;

/**
 * Fisher's exact test of a 2 x 2 table (hits and misses in two groups of runs), two-sided: the
 * sum of the probabilities, under the hypergeometric distribution of Apache Commons Math, of
 * every table with the same margins that is at most as likely as the one observed.
 */
public final class FisherExact {

    /** Relative tolerance when comparing table probabilities, as R's and SciPy's implementations use. */
    private static final double TOLERANCE = 1 + 1e-7;

    private FisherExact() {
    }

    /**
     * @param hitsA runs of group A in which it happened
     * @param runsA runs of group A, at least {@code hitsA}
     * @param hitsB runs of group B in which it happened
     * @param runsB runs of group B, at least {@code hitsB}
     * @return the two-sided p-value
     */
    public static double twoSided(int hitsA, int runsA, int hitsB, int runsB) {
        if (hitsA < 0 || hitsB < 0 || hitsA > runsA || hitsB > runsB || runsA + runsB == 0) {
            throw new IllegalArgumentException("a 2 x 2 table needs 0 <= hits <= runs, got " + hitsA + " of " + runsA
                    + " and " + hitsB + " of " + runsB);
        }
        HypergeometricDistribution h = new HypergeometricDistribution(null, runsA + runsB, hitsA + hitsB, runsA);
        double observed = h.probability(hitsA);
        double p = 0;
        for (int x = h.getSupportLowerBound(); x <= h.getSupportUpperBound(); x++) {
            double px = h.probability(x);
            if (px <= observed * TOLERANCE) {
                p += px;
            }
        }
        return Math.min(1, p);
    }
}
