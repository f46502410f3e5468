package io.rtaware.app.cli;

import io.rtaware.core.time.Durations;
import picocli.CommandLine;

/** Converts {@code 10ms}, {@code 2.5ms}, {@code 1s}, bare milliseconds, to nanoseconds. */
public final class DurationConverter implements CommandLine.ITypeConverter<Long> {

    @Override
    public Long convert(String value) {
        try {
            return Durations.parseNanos(value);
        } catch (IllegalArgumentException e) {
            throw new CommandLine.TypeConversionException(e.getMessage());
        }
    }
}
