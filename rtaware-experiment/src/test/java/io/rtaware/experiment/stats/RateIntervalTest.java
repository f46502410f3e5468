package io.rtaware.experiment.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class RateIntervalTest {

    /** Values from the Wilson score formula with z = 1.959964, worked by hand. */
    @Test
    void matchesTheWilsonScoreInterval() {
        RateInterval none = RateInterval.of(0, 10);
        assertEquals(0.0, none.lower(), 1e-9, "no hit: the interval starts at 0, not below it");
        assertEquals(0.27754, none.upper(), 1e-4);
        RateInterval three = RateInterval.of(3, 10);
        assertEquals(0.3, three.rate(), 1e-12);
        assertEquals(0.10779, three.lower(), 1e-4);
        assertEquals(0.60322, three.upper(), 1e-4);
        RateInterval all = RateInterval.of(10, 10);
        assertEquals(0.72246, all.lower(), 1e-4);
        assertEquals(1.0, all.upper(), 1e-9);
        assertEquals("3 of 10 (30 %, 95 % CI 11-60 %)", three.text());
    }

    @Test
    void tenRunsSeparateNoneFromMostButNotFromOneInThree() {
        assertTrue(RateInterval.of(0, 10).separatedFrom(RateInterval.of(7, 10)), "[0, 28 %] and [40, 89 %]");
        assertFalse(RateInterval.of(0, 10).separatedFrom(RateInterval.of(3, 10)), "[0, 28 %] and [11, 60 %] overlap");
        assertFalse(RateInterval.of(0, 3).separatedFrom(RateInterval.of(3, 3)), "three runs separate nothing: [0, 56 %], [44, 100 %]");
    }

    @Test
    void impossibleCountsAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> RateInterval.of(0, 0));
        assertThrows(IllegalArgumentException.class, () -> RateInterval.of(4, 3));
        assertThrows(IllegalArgumentException.class, () -> RateInterval.of(-1, 3));
    }
}
