package io.rtaware.experiment.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class WelchTestTest {

    /**
     * The first worked example of the Wikipedia article "Welch's t-test" (samples A1 and A2 of
     * 15 values each): published t = -2.46, df = 24.99 (about 25), p = 0.021. The exact t and df
     * below were computed by hand from the sums of the data; p by numerical integration of the
     * t density (Simpson's rule, outside this code base): 0.021378.
     */
    @Test
    void matchesPublishedTextbookExample() {
        double[] a1 = {27.5, 21.0, 19.0, 23.6, 17.0, 17.9, 16.9, 20.1, 21.9, 22.6, 23.1, 19.6, 19.0, 21.7, 21.4};
        double[] a2 = {27.1, 22.0, 20.8, 23.4, 23.4, 23.5, 25.8, 22.0, 24.8, 20.2, 21.9, 22.1, 22.9, 20.5, 24.4};
        WelchTest w = WelchTest.of(a1, a2);
        assertTrue(w.applicable());
        assertEquals(-2.455356, w.t(), 1e-6);
        assertEquals(24.988529, w.df(), 1e-5);
        assertEquals(0.021378, w.p(), 1e-5);
        assertEquals(1 - w.p(), w.confidence(), 1e-12);
        assertEquals(2.455356, WelchTest.of(a2, a1).t(), 1e-6);
    }

    /**
     * {1..5} against {2,4,..,10}: means 3 and 6, variances 2.5 and 10, so the standard error is
     * sqrt(0.5 + 2) and t = -3 / sqrt(2.5) = -1.897367; df = 2.5^2 / (0.5^2/4 + 2^2/4) = 5.882353;
     * p (numerical integration of the t density) = 0.107531.
     */
    @Test
    void matchesHandComputedSmallExample() {
        WelchTest w = WelchTest.of(new double[] {1, 2, 3, 4, 5}, new double[] {2, 4, 6, 8, 10});
        assertEquals(-1.897367, w.t(), 1e-6);
        assertEquals(5.882353, w.df(), 1e-6);
        assertEquals(0.107531, w.p(), 1e-5);
    }

    @Test
    void degenerateSamplesAreNotApplicableNotNaN() {
        WelchTest few = WelchTest.of(new double[] {1}, new double[] {2, 3});
        assertFalse(few.applicable());
        assertNull(few.t());
        assertNull(few.p());
        assertTrue(few.note().contains("at least 2 values"), few.note());
        WelchTest flat = WelchTest.of(new double[] {4, 4, 4}, new double[] {5, 5});
        assertFalse(flat.applicable());
        assertTrue(flat.note().contains("no variance"), flat.note());
        WelchTest oneFlat = WelchTest.of(new double[] {4, 4, 4}, new double[] {5, 6, 7});
        assertTrue(oneFlat.applicable());
        assertEquals(2.0, oneFlat.df(), 1e-12);
        WelchTest nanIgnored = WelchTest.of(new double[] {1, 2, Double.NaN}, new double[] {Double.NaN});
        assertFalse(nanIgnored.applicable());
    }

    @Test
    void sampleStatsUseNMinusOneAndLeaveUndefinedNull() {
        SampleStats s = SampleStats.of(new double[] {2, 4, 4, 4, 5, 5, 7, 9});
        assertEquals(8, s.n());
        assertEquals(5.0, s.mean(), 1e-12);
        assertEquals(Math.sqrt(32.0 / 7), s.sd(), 1e-12);
        assertEquals(2.0, s.min());
        assertEquals(9.0, s.max());
        SampleStats one = SampleStats.of(new double[] {3});
        assertEquals(3.0, one.mean());
        assertNull(one.sd());
        SampleStats none = SampleStats.of(new double[] {Double.NaN});
        assertEquals(0, none.n());
        assertNull(none.mean());
    }

    /**
     * Two samples of 10 with variance 1 each: df = 18, standard error sqrt(0.2) = 0.447214; from
     * printed t tables t(0.975, 18) = 2.1009 and t(0.80, 18) = 0.8620, so the smallest difference
     * detected at alpha 0.05 with 80 % power is (2.1009 + 0.8620) * 0.447214 = 1.3250.
     */
    @Test
    void detectableDifferenceIsThePowerOfTheTestAsASize() {
        assertEquals(1.3250, WelchTest.detectable(1, 10, 1, 10), 2e-4);
        double[] a = {-1.5, -0.5, 0.5, 1.5, 0, 0, 1, -1, 2, -2};
        double[] b = {8.5, 9.5, 10.5, 11.5, 10, 10, 11, 9, 12, 8};
        WelchTest w = WelchTest.of(a, b);
        double variance = 15.0 / 9; // both samples: sum of squared deviations 15 over n - 1
        assertEquals(WelchTest.detectable(variance, 10, variance, 10), w.detectableDifference(), 1e-12);
        assertEquals(1.3250 * Math.sqrt(variance), w.detectableDifference(), 3e-4,
                "scales with the spread: sqrt(15/9) times the unit-variance figure");
        assertNull(WelchTest.of(new double[] {1}, b).detectableDifference(), "n/a test: no power figure");
    }
}
