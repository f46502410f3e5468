package io.rtaware.core.time;

import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Parses and prints the human durations used on the command line and in files:
 * {@code 10ms}, {@code 2.5ms}, {@code 500us}, {@code 1s}, {@code 250ns}, {@code 2m}. A bare
 * number is milliseconds, the unit the paper uses for periods.
 */
public final class Durations {

    private static final Pattern FORMAT =
            Pattern.compile("\\s*([0-9]+(?:\\.[0-9]+)?|\\.[0-9]+)\\s*(ns|us|µs|ms|s|m|min)?\\s*");

    private Durations() {
    }

    /**
     * @param text a duration such as {@code 10ms}
     * @return the duration in nanoseconds
     * @throws IllegalArgumentException naming the text when it is not a duration
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
        String unit = m.group(2) == null ? "ms" : m.group(2);
        double nanosPerUnit = switch (unit) {
            case "ns" -> 1.0;
            case "us", "µs" -> 1e3;
            case "ms" -> 1e6;
            case "s" -> 1e9;
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
     * @return a short human form: {@code 10ms}, {@code 2.5ms}, {@code 750us}, {@code 2s};
     *     negative spans get a minus sign ({@code -5ms})
     */
    public static String format(long ns) {
        if (ns < 0 && ns != Long.MIN_VALUE) {
            return "-" + format(-ns);
        }
        if (ns % 1_000_000_000L == 0 && ns != 0) {
            return ns / 1_000_000_000L + "s";
        }
        if (ns >= 1_000_000L) {
            return trim(ns / 1e6) + "ms";
        }
        if (ns >= 1_000L) {
            return trim(ns / 1e3) + "us";
        }
        return ns + "ns";
    }

    private static String trim(double v) {
        if (v == Math.rint(v)) {
            return Long.toString((long) v);
        }
        return String.format(Locale.ROOT, "%.3f", v).replaceAll("0+$", "");
    }
}
