package io.rtaware.experiment.stats;

import java.util.Arrays;
import org.apache.commons.math3.distribution.ChiSquaredDistribution;
import org.apache.commons.math3.distribution.FDistribution;
import org.apache.commons.math3.stat.ranking.NaturalRanking;
import org.apache.commons.math3.stat.ranking.TiesStrategy;

/**
 * Treatments compared within blocks (a randomized complete block design: here the sets, each run
 * once with every world seed): the two-way analysis of variance without replication, and
 * Friedman's rank test (with the usual correction for ties), both with the block as the second
 * factor, so that what the blocks share (the seed's world) is taken out of the comparison. The
 * p-values come from Apache Commons Math's F and chi-squared distributions.
 *
 * @param blocks the complete blocks, b
 * @param treatments the treatments, k
 * @param f the ANOVA's F of the treatments against the residual, or NaN when the residual is zero
 * @param dfTreatments k - 1
 * @param dfError (k - 1)(b - 1)
 * @param anovaP the ANOVA's p-value, or NaN when undefined
 * @param friedmanChi2 Friedman's statistic, or NaN when every block ties throughout
 * @param friedmanP its p-value (chi-squared with k - 1 degrees of freedom), or NaN
 */
public record BlockedComparison(int blocks, int treatments, double f, int dfTreatments, int dfError, double anovaP,
                                double friedmanChi2, double friedmanP) {

    /**
     * @param values {@code values[block][treatment]}: at least 2 blocks of at least 2 treatments,
     *     every block complete and every value finite
     * @return both tests
     */
    public static BlockedComparison of(double[][] values) {
        int b = values.length;
        if (b < 2 || values[0].length < 2 || Arrays.stream(values).anyMatch(r -> r.length != values[0].length
                || Arrays.stream(r).anyMatch(v -> !Double.isFinite(v)))) {
            throw new IllegalArgumentException("a blocked comparison needs at least 2 complete blocks of at least 2 "
                    + "finite values each");
        }
        int k = values[0].length;
        double grand = Arrays.stream(values).flatMapToDouble(Arrays::stream).average().orElseThrow();
        double ssTreatments = 0;
        for (int t = 0; t < k; t++) {
            double mean = 0;
            for (double[] block : values) {
                mean += block[t] / b;
            }
            ssTreatments += b * (mean - grand) * (mean - grand);
        }
        double ssBlocks = 0;
        double ssTotal = 0;
        for (double[] block : values) {
            double mean = Arrays.stream(block).average().orElseThrow();
            ssBlocks += k * (mean - grand) * (mean - grand);
            for (double v : block) {
                ssTotal += (v - grand) * (v - grand);
            }
        }
        int dfT = k - 1;
        int dfE = (k - 1) * (b - 1);
        double ssError = Math.max(0, ssTotal - ssTreatments - ssBlocks);
        double f = ssError == 0 ? Double.NaN : (ssTreatments / dfT) / (ssError / dfE);
        double anovaP = Double.isNaN(f) ? Double.NaN : 1 - new FDistribution(dfT, dfE).cumulativeProbability(f);
        return new BlockedComparison(b, k, f, dfT, dfE, anovaP, friedman(values)[0], friedman(values)[1]);
    }

    /** @return Friedman's statistic, corrected for ties, and its p-value */
    private static double[] friedman(double[][] values) {
        int b = values.length;
        int k = values[0].length;
        double[] rankSums = new double[k];
        double ties = 0;
        NaturalRanking ranking = new NaturalRanking(TiesStrategy.AVERAGE);
        for (double[] block : values) {
            double[] ranks = ranking.rank(block);
            for (int t = 0; t < k; t++) {
                rankSums[t] += ranks[t];
            }
            double[] sorted = block.clone();
            Arrays.sort(sorted);
            for (int i = 0; i < k; ) {
                int j = i;
                while (j < k && sorted[j] == sorted[i]) {
                    j++;
                }
                ties += Math.pow(j - i, 3) - (j - i);
                i = j;
            }
        }
        double sumSquares = Arrays.stream(rankSums).map(r -> r * r).sum();
        double chi2 = 12.0 / (b * k * (k + 1.0)) * sumSquares - 3.0 * b * (k + 1);
        double correction = 1 - ties / (b * (Math.pow(k, 3) - k));
        if (correction <= 0) {
            return new double[] {Double.NaN, Double.NaN};
        }
        chi2 /= correction;
        return new double[] {chi2, 1 - new ChiSquaredDistribution(k - 1).cumulativeProbability(chi2)};
    }
}
