package io.rtaware.app.cli;

import io.rtaware.core.time.Durations;
import picocli.CommandLine;

/**
 * Converts {@code 10ms}, {@code 2.5ms}, {@code 1s} to nanoseconds, for every option that takes a
 * duration (their placeholder is {@code DURATION}). A number without a unit, other than 0, is refused
 * with one line naming the value and the units ({@link Durations#parseNanos}).
 */
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
