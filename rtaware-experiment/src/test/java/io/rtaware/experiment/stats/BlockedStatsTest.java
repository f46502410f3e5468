package io.rtaware.experiment.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

/** The blocked comparison, paired differences, Fisher's exact test and the two-sample intervals, against known values. */
class BlockedStatsTest {

    @Test
    void twoWayAnovaOfTwoByTwoIsThePairedTSquared() {
        // treatments (columns) 1 vs 2 in two blocks: differences 1 and 2, paired t = 3, so F(1, 1) = 9
        BlockedComparison c = BlockedComparison.of(new double[][] {{1, 2}, {3, 5}});
        assertEquals(9.0, c.f(), 1e-12);
        assertEquals(1, c.dfTreatments());
        assertEquals(1, c.dfError());
        assertEquals(1 - 2 / Math.PI * Math.atan(3), c.anovaP(), 1e-9, "F(1, 1) is the square of a Cauchy variable");
    }

    @Test
    void friedmanMatchesRsRoundingTimesExample() {
        // R's ?friedman.test, Hollander & Wolfe (1973) p. 140: chi-squared 11.143, df 2, p 0.003805
        double[][] times = {{5.40, 5.50, 5.55}, {5.85, 5.70, 5.75}, {5.20, 5.60, 5.50}, {5.55, 5.50, 5.40},
            {5.90, 5.85, 5.70}, {5.45, 5.55, 5.60}, {5.40, 5.40, 5.35}, {5.45, 5.50, 5.35}, {5.25, 5.15, 5.00},
            {5.85, 5.80, 5.70}, {5.25, 5.20, 5.10}, {5.65, 5.55, 5.45}, {5.60, 5.35, 5.45}, {5.05, 5.00, 4.95},
            {5.50, 5.50, 5.40}, {5.45, 5.55, 5.50}, {5.55, 5.55, 5.35}, {5.45, 5.50, 5.55}, {5.50, 5.45, 5.25},
            {5.65, 5.60, 5.40}, {5.70, 5.65, 5.55}, {6.30, 6.30, 6.25}};
        BlockedComparison c = BlockedComparison.of(times);
        assertEquals(11.143, c.friedmanChi2(), 5e-4);
        assertEquals(0.003805, c.friedmanP(), 5e-7);
        assertEquals(22, c.blocks());
        assertEquals(3, c.treatments());
    }

    @Test
    void incompleteBlocksAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> BlockedComparison.of(new double[][] {{1, 2}, {3}}));
        assertThrows(IllegalArgumentException.class, () -> BlockedComparison.of(new double[][] {{1, 2}}));
        assertThrows(IllegalArgumentException.class, () -> BlockedComparison.of(new double[][] {{1, 2}, {3, Double.NaN}}));
    }

    @Test
    void pairedDifferenceHasTheTInterval() {
        PairedDifference d = PairedDifference.of(new double[] {2, 5}, new double[] {1, 3});
        assertEquals(1.5, d.mean(), 1e-12);
        // se 0.5, t(0.975, 1) = 12.7062
        assertEquals(1.5 - 12.7062047 * 0.5, d.lower(), 1e-6);
        assertEquals(1.5 + 12.7062047 * 0.5, d.upper(), 1e-6);
        assertEquals(Double.NaN, PairedDifference.of(new double[] {1}, new double[] {0}).lower());
    }

    @Test
    void fisherExactTwoSided() {
        assertEquals(34.0 / 70, FisherExact.twoSided(3, 4, 1, 4), 1e-12);
        assertEquals(2.0 / 252, FisherExact.twoSided(5, 5, 0, 5), 1e-12);
        assertEquals(1.0, FisherExact.twoSided(0, 3, 0, 4), 1e-12);
        assertThrows(IllegalArgumentException.class, () -> FisherExact.twoSided(4, 3, 0, 4));
    }

    @Test
    void welchIntervalOfTheDifferenceAndFIntervalOfTheRatio() {
        SampleStats a = new SampleStats(10, 10.0, 2.0, null, null);
        SampleStats b = new SampleStats(10, 8.0, 2.0, null, null);
        MeanInterval diff = MeanInterval.meanDifference(a, b);
        // se sqrt(0.4 + 0.4), df 18, t(0.975, 18) = 2.100922
        assertEquals(2.0, diff.estimate(), 1e-12);
        assertEquals(2.0 - 2.100922 * Math.sqrt(0.8), diff.lower(), 1e-5);
        assertEquals(2.0 + 2.100922 * Math.sqrt(0.8), diff.upper(), 1e-5);
        MeanInterval ratio = MeanInterval.varianceRatio(a, b);
        // F(0.975; 9, 9) = 4.025994
        assertEquals(1.0, ratio.estimate(), 1e-12);
        assertEquals(1 / 4.025994, ratio.lower(), 1e-5);
        assertEquals(4.025994, ratio.upper(), 1e-4);
    }
}
