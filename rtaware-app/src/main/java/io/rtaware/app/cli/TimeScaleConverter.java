package io.rtaware.app.cli;

import picocli.CommandLine;

/**
 * Converts {@code --time-scale K}: world seconds per wall second, a positive finite number. A bad
 * value ends the command with one line naming it and exit status 2, like any other bad option.
 */
public final class TimeScaleConverter implements CommandLine.ITypeConverter<Double> {

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
        return k;
    }
}
