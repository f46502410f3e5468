package io.rtaware.core.analysis;

import io.rtaware.core.report.Rounding;
import java.math.BigDecimal;
import java.math.MathContext;
import java.math.RoundingMode;
import java.util.Locale;

/** Numbers of the advice: rounding of suggested periods and figures in messages. Stateless. */
final class Num {

    /** Significant digits of a suggested period. */
    private static final int DIGITS = 3;

    private Num() {
    }

    /** @return {@code ms} rounded up to {@value #DIGITS} significant digits (155.19 -> 156) */
    static double ceilPeriod(double ms) {
        return round(ms, RoundingMode.CEILING);
    }

    /** @return {@code ms} rounded down to {@value #DIGITS} significant digits (32.09 -> 32) */
    static double floorPeriod(double ms) {
        return round(ms, RoundingMode.FLOOR);
    }

    private static double round(double ms, RoundingMode mode) {
        if (!(ms > 0) || Double.isInfinite(ms)) {
            return ms;
        }
        return BigDecimal.valueOf(ms).round(new MathContext(DIGITS, mode)).doubleValue();
    }

    static double round2(double v) {
        return Rounding.toDecimals(v, 2);
    }

    static double round3(double v) {
        return Rounding.toDecimals(v, 3);
    }

    /** @return milliseconds for a message, with the unit: {@code 32.092 ms} */
    static String ms(double v) {
        return num(v) + " ms";
    }

    /** Up to three decimals, never a dangling point; tiny values in %g. */
    static String num(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return Long.toString((long) v);
        }
        if (v != 0 && Math.abs(v) < 0.0005 || !Double.isFinite(v) || Math.abs(v) >= 1e15) {
            return String.format(Locale.ROOT, "%.3g", v);
        }
        return String.format(Locale.ROOT, "%.3f", v).replaceAll("0+$", "").replaceAll("\\.$", "");
    }
}
