package io.rtaware.core.report;

/**
 * Rounds numbers for reports to a few decimals without the overflow of
 * {@code Math.round(v * 1000) / 1000.0}: a value too large to have fractional digits (at or
 * beyond 2^52 once scaled) is returned as it is, and a non-finite value stays non-finite (the
 * report writers turn it into {@code null}).
 */
public final class Rounding {

    /** Beyond this magnitude a double has no fractional digits, so there is nothing to round. */
    private static final double NO_FRACTION = 0x1p52;

    private Rounding() {
    }

    /**
     * @param v a value
     * @param decimals digits after the decimal point, 0 to 9
     * @return v rounded half up to that many decimals, or v itself when it is not finite or too
     *     large to carry those decimals
     */
    public static double toDecimals(double v, int decimals) {
        if (decimals < 0 || decimals > 9) {
            throw new IllegalArgumentException("decimals must be 0..9, got " + decimals);
        }
        double factor = Math.pow(10, decimals);
        double scaled = v * factor;
        if (!Double.isFinite(scaled) || Math.abs(scaled) >= NO_FRACTION) {
            return v;
        }
        return Math.round(scaled) / factor;
    }
}
