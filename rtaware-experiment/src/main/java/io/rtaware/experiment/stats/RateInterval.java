package io.rtaware.experiment.stats;

import java.util.Locale;
import org.apache.commons.math3.stat.interval.ConfidenceInterval;
import org.apache.commons.math3.stat.interval.WilsonScoreInterval;

/**
 * The share of runs in which something happened (a collision, a near miss), with its Wilson score
 * interval at {@link #CONFIDENCE}: the interval that keeps its coverage at the few runs and the
 * rates near 0 or 1 of a sweep point, where the normal approximation gives negative bounds.
 * Two points whose intervals do not overlap differ at about that confidence or better.
 *
 * @param hits runs in which it happened
 * @param runs runs
 * @param rate {@code hits / runs}
 * @param lower the interval's lower bound, 0 to 1
 * @param upper its upper bound, 0 to 1
 */
public record RateInterval(int hits, int runs, double rate, double lower, double upper) {

    /** The interval's confidence level. */
    public static final double CONFIDENCE = 0.95;

    /**
     * @param hits runs in which it happened, 0 to {@code runs}
     * @param runs runs, at least 1
     * @return the rate and its interval
     */
    public static RateInterval of(int hits, int runs) {
        if (runs < 1 || hits < 0 || hits > runs) {
            throw new IllegalArgumentException("a rate needs 0 <= hits <= runs and runs >= 1, got " + hits + " of " + runs);
        }
        ConfidenceInterval ci = new WilsonScoreInterval().createInterval(runs, hits, CONFIDENCE);
        return new RateInterval(hits, runs, (double) hits / runs, Math.max(0, ci.getLowerBound()),
                Math.min(1, ci.getUpperBound()));
    }

    /**
     * @param other another point's rate
     * @return true if the two intervals do not overlap
     */
    public boolean separatedFrom(RateInterval other) {
        return lower > other.upper || other.lower > upper;
    }

    /** @return e.g. {@code 3 of 10 (30 %, 95 % CI 11-60 %)} */
    public String text() {
        return String.format(Locale.ROOT, "%d of %d (%.0f %%, %.0f %% CI %.0f-%.0f %%)", hits, runs, 100 * rate,
                100 * CONFIDENCE, 100 * lower, 100 * upper);
    }
}
