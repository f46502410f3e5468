package io.rtaware.core.time;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class DurationsTest {

    @Test
    void parsesEveryUnit() {
        assertEquals(10_000_000L, Durations.parseNanos("10ms"), "10ms");
        assertEquals(2_500_000L, Durations.parseNanos("2.5ms"), "2.5ms");
        assertEquals(500_000L, Durations.parseNanos("500us"), "500us");
        assertEquals(500_000L, Durations.parseNanos("500µs"), "500µs");
        assertEquals(1_000_000_000L, Durations.parseNanos("1s"), "1s");
        assertEquals(250L, Durations.parseNanos("250ns"), "250ns");
        assertEquals(120_000_000_000L, Durations.parseNanos("2m"), "2m is minutes");
        assertEquals(120_000_000_000L, Durations.parseNanos("2min"), "2min");
        assertEquals(1_500_000L, Durations.parseNanos(" 1.5 MS "), "spaces and case are tolerated");
        assertEquals(500_000L, Durations.parseNanos(".5ms"), "leading dot");
    }

    @Test
    void garbageIsRejectedWithAMessageNamingTheText() {
        for (String text : new String[] {"ten ms", "10 parsecs", "", "-5ms", "1.2.3ms", "ms"}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Durations.parseNanos(text), text);
            assertEquals("'" + text + "' is not a duration (examples: 10ms, 2.5ms, 500us, 1s)", e.getMessage(),
                    "message for '" + text + "'");
        }
        assertEquals("missing duration",
                assertThrows(IllegalArgumentException.class, () -> Durations.parseNanos(null)).getMessage(), "null");
        assertEquals("'9999999999999s' is too long a duration",
                assertThrows(IllegalArgumentException.class, () -> Durations.parseNanos("9999999999999s")).getMessage(),
                "overflow");
    }

    @Test
    void aNumberWithoutAUnitIsRefusedNamingTheValueAndTheUnits() {
        // 'bench --duration 10' ran 10 ms and 'player-probe --listen 3' listened 3 ms: a bare number is a guess
        for (String text : new String[] {"10", "3", " 2.5 ", ".5"}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Durations.parseNanos(text), text);
            assertEquals("'" + text + "' has no unit: a duration needs one of ns, us, ms, s, min, h (e.g. " + text.strip()
                    + "ms or " + text.strip() + "s)", e.getMessage(), "message for '" + text + "'");
        }
        assertEquals(0L, Durations.parseNanos("0"), "zero is zero in every unit");
        assertEquals(0L, Durations.parseNanos("0.0"), "zero written with a point");
    }

    @Test
    void formatsShortHumanForms() {
        assertEquals("10ms", Durations.format(10_000_000L), "ms");
        assertEquals("2.5ms", Durations.format(2_500_000L), "fractional ms");
        assertEquals("750us", Durations.format(750_000L), "us");
        assertEquals("2s", Durations.format(2_000_000_000L), "s");
        assertEquals("0ns", Durations.format(0), "zero");
        assertEquals("-5ms", Durations.format(-5_000_000L), "negative spans keep their unit");
        assertEquals(Durations.parseNanos("2.5ms"), Durations.parseNanos(Durations.format(2_500_000L)), "round trip");
    }

    @Test
    void acceptsHoursLikeMinutes() {
        assertEquals(3_600_000_000_000L, Durations.parseNanos("1h"), "1h");
        assertEquals(5_400_000_000_000L, Durations.parseNanos("1.5h"), "1.5h");
    }

    @Test
    void formatsEveryDurationExactlyNeverADanglingPoint() {
        assertEquals("1ns", Durations.format(1), "1 ns");
        assertEquals("1000.1us", Durations.format(1_000_100L), "not 1.ms");
        assertEquals("1.001ms", Durations.format(1_001_000L), "three decimals of ms");
        assertEquals("1ns", Durations.formatMillis(1e-6), "a period of 1e-6 ms");
        assertEquals("10ms", Durations.formatMillis(10.0), "whole ms");
        assertEquals("2.5ms", Durations.formatMillis(2.5), "fractional ms");
        assertEquals("0ns", Durations.formatMillis(1e-300), "below a nanosecond");
        assertEquals("-", Durations.formatMillis(Double.NaN), "no value");
        for (long ns : new long[] {1, 999, 1_000, 1_001, 999_999, 1_000_001, 123_456_789L, 60_000_000_001L}) {
            assertEquals(ns, Durations.parseNanos(Durations.format(ns)), "round trip of " + ns + " ns");
        }
    }
}
