package io.rtaware.core.time;

import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Parses and prints the human durations used on the command line and in files:
 * {@code 10ms}, {@code 2.5ms}, {@code 500us}, {@code 1s}, {@code 250ns}, {@code 2m}, {@code 1h}. Every
 * duration names its unit: a bare number other than zero is refused ({@code --duration 10} once ran for
 * 10 ms where 10 s was meant), with a message naming the value and the accepted units.
 */
public final class Durations {

    private static final Pattern FORMAT =
            Pattern.compile("\\s*([0-9]+(?:\\.[0-9]+)?|\\.[0-9]+)\\s*(ns|us|µs|ms|s|min|m|h)?\\s*");

    /** The units {@link #parseNanos} accepts, as a message lists them. */
    public static final String UNITS = "ns, us, ms, s, min, h";

    private Durations() {
    }

    /**
     * @param text a duration such as {@code 10ms}
     * @return the duration in nanoseconds
     * @throws IllegalArgumentException naming the text when it is not a duration, or when it is a
     *     number other than zero without a unit
     */
    public static long parseNanos(String text) {
        if (text == null) {
            throw new IllegalArgumentException("missing duration");
        }
        Matcher m = FORMAT.matcher(text.toLowerCase(Locale.ROOT));
        if (!m.matches()) {
            throw new IllegalArgumentException("'" + text + "' is not a duration (examples: 10ms, 2.5ms, 500us, 1s)");
        }
        double value = Double.parseDouble(m.group(1));
        if (m.group(2) == null) {
            if (value == 0) {
                return 0;
            }
            String number = text.strip();
            throw new IllegalArgumentException("'" + text + "' has no unit: a duration needs one of " + UNITS
                    + " (e.g. " + number + "ms or " + number + "s)");
        }
        String unit = m.group(2);
        double nanosPerUnit = switch (unit) {
            case "ns" -> 1.0;
            case "us", "µs" -> 1e3;
            case "ms" -> 1e6;
            case "s" -> 1e9;
            case "h" -> 3600e9;
            default -> 60e9;
        };
        double ns = value * nanosPerUnit;
        if (ns > Long.MAX_VALUE / 4) {
            throw new IllegalArgumentException("'" + text + "' is too long a duration");
        }
        return Math.round(ns);
    }

    /**
     * @param ns a duration in nanoseconds
     * @return milliseconds as a double, the unit of the reports
     */
    public static double toMillis(long ns) {
        return ns / 1e6;
    }

    /**
     * @param ns a duration in nanoseconds
     * @return a short human form that reads back to the same nanoseconds: {@code 10ms},
     *     {@code 2.5ms}, {@code 750us}, {@code 1000.1us}, {@code 1ns}, {@code 2s}; negative
     *     spans get a minus sign ({@code -5ms})
     */
    public static String format(long ns) {
        if (ns < 0 && ns != Long.MIN_VALUE) {
            return "-" + format(-ns);
        }
        if (ns % 1_000_000_000L == 0 && ns != 0) {
            return ns / 1_000_000_000L + "s";
        }
        if (ns >= 1_000_000L && ns % 1_000L == 0) {
            return decimal(ns / 1_000L, 3) + "ms";
        }
        if (ns >= 1_000L) {
            return decimal(ns, 3) + "us";
        }
        return ns + "ns";
    }

    /**
     * Prints a period or time given in milliseconds (as reports hold them) like {@link #format}.
     *
     * @param ms milliseconds; rounded to the nanosecond
     * @return e.g. {@code 10ms}, {@code 1ns} for 1e-6 ms, or {@code -} when there is no finite value
     */
    public static String formatMillis(double ms) {
        if (!Double.isFinite(ms)) {
            return "-";
        }
        double ns = ms * 1e6;
        if (Math.abs(ns) >= Long.MAX_VALUE / 2.0) {
            return String.format(Locale.ROOT, "%.3gs", ms / 1e3);
        }
        return format(Math.round(ns));
    }

    /** @return units / 10^decimals without trailing zeros, e.g. (1001, 3) gives 1.001 */
    private static String decimal(long units, int decimals) {
        long scale = (long) Math.pow(10, decimals);
        long whole = units / scale;
        long fraction = units % scale;
        if (fraction == 0) {
            return Long.toString(whole);
        }
        String digits = String.format(Locale.ROOT, "%0" + decimals + "d", fraction).replaceAll("0+$", "");
        return whole + "." + digits;
    }
}
