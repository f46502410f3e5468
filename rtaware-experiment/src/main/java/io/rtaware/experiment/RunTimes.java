package io.rtaware.experiment;

import java.time.Instant;
import java.time.format.DateTimeFormatter;
import java.time.format.DateTimeParseException;
import java.time.temporal.ChronoUnit;

/**
 * When a run of an experiment was made: from just before its process started to just after it
 * ended, by the experiment's wall clock in UTC (results.csv {@code started_utc}, {@code ended_utc},
 * ISO-8601 to the millisecond, e.g. {@code 2026-11-28T02:08:41.123Z}). A row made before the
 * times were recorded has {@link #UNRECORDED}.
 *
 * @param startedUtc when the run's process was about to start, or null if not recorded
 * @param endedUtc when it had ended, or null if not recorded
 */
public record RunTimes(Instant startedUtc, Instant endedUtc) {

    /** The times of a row that predates them. */
    public static final RunTimes UNRECORDED = new RunTimes(null, null);

    /**
     * Truncates to the millisecond and checks the order.
     *
     * @param startedUtc when the run's process was about to start, or null
     * @param endedUtc when it had ended, or null
     */
    public RunTimes {
        if ((startedUtc == null) != (endedUtc == null)) {
            throw new IllegalArgumentException("a run has both started_utc and ended_utc or neither, got "
                    + startedUtc + " and " + endedUtc);
        }
        if (startedUtc != null) {
            startedUtc = startedUtc.truncatedTo(ChronoUnit.MILLIS);
            endedUtc = endedUtc.truncatedTo(ChronoUnit.MILLIS);
            if (endedUtc.isBefore(startedUtc)) {
                throw new IllegalArgumentException("ended_utc " + endedUtc + " is before started_utc " + startedUtc);
            }
        }
    }

    /**
     * @param instant an instant, or null
     * @return it as ISO-8601 UTC ({@code 2026-11-28T02:08:41.123Z}), or empty for null
     */
    static String format(Instant instant) {
        return instant == null ? "" : DateTimeFormatter.ISO_INSTANT.format(instant);
    }

    /**
     * @param text ISO-8601 UTC as written by {@link #format}, or empty
     * @return the instant, or null for empty
     * @throws IllegalArgumentException naming the text if it is not an ISO-8601 instant
     */
    static Instant parse(String text) {
        if (text.isEmpty()) {
            return null;
        }
        try {
            return Instant.parse(text);
        } catch (DateTimeParseException e) {
            throw new IllegalArgumentException("'" + text + "' is not an ISO-8601 UTC time (e.g. 2026-11-28T02:08:41.123Z)");
        }
    }
}
