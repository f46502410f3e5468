package io.rtaware.app.cli;

import picocli.CommandLine;

/**
 * Converts {@code --time-scale K}: world seconds per wall second, from {@value #MIN} to
 * {@value #MAX}. Outside that range the clock is useless (at 1e-300 world time never advances and
 * the command hangs; at 1e300 a whole run passes in less than a nanosecond of wall time). A bad
 * value ends the command with one line naming it and exit status 2, like any other bad option.
 */
public final class TimeScaleConverter implements CommandLine.ITypeConverter<Double> {

    /** Slowest world time accepted: a thousand times slower than wall time. */
    public static final double MIN = 0.001;
    /** Fastest world time accepted: a thousand times faster than wall time (a 10 ms period is 10 us of wall time). */
    public static final double MAX = 1000;

    @Override
    public Double convert(String value) {
        double k;
        try {
            k = Double.parseDouble(value.trim());
        } catch (NumberFormatException e) {
            k = Double.NaN;
        }
        if (!(k > 0) || Double.isInfinite(k)) {
            throw new CommandLine.TypeConversionException(
                    "'" + value + "' is not a time scale: it must be a positive number of world seconds per wall second");
        }
        if (k < MIN || k > MAX) {
            throw new CommandLine.TypeConversionException("time scale '" + value + "' is out of range: it must be from "
                    + MIN + " to " + (long) MAX + " world seconds per wall second (docs/troubleshooting.md)");
        }
        return k;
    }
}
