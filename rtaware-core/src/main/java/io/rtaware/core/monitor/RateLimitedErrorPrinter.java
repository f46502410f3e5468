package io.rtaware.core.monitor;

import io.rtaware.core.time.Clock;
import io.rtaware.core.time.SystemClock;
import java.io.PrintStream;
import java.util.Objects;

/**
 * The default {@link FrameworkErrorHandler}: one line per fault, at most one line per second of
 * wall time (like the {@link ConsoleReporter}); faults in between are folded into the next line's
 * count, so none is dropped silently. A listener that throws on every cycle of a 1 kHz task thus
 * prints one line a second, not a thousand. Thread-safe.
 */
public final class RateLimitedErrorPrinter implements FrameworkErrorHandler {

    private static final long LINE_INTERVAL_NS = 1_000_000_000L;

    private final PrintStream out;
    private final Clock wallClock;
    private final LinePacer pacer = new LinePacer(LINE_INTERVAL_NS, LINE_INTERVAL_NS);
    private long folded;

    /** Prints to standard error, limited in wall time. */
    public RateLimitedErrorPrinter() {
        this(System.err, new SystemClock());
    }

    /**
     * @param out where lines go
     * @param wallClock the clock of the one-line-per-second limit (wall time: it protects a reader)
     */
    public RateLimitedErrorPrinter(PrintStream out, Clock wallClock) {
        this.out = Objects.requireNonNull(out, "out");
        this.wallClock = Objects.requireNonNull(wallClock, "wallClock");
    }

    @Override
    public synchronized void onError(String source, Throwable error) {
        long nowNs = wallClock.nanos();
        if (!pacer.due(nowNs)) {
            folded++;
            return;
        }
        StringBuilder line = new StringBuilder("rtaware: framework error in ").append(source).append(": ")
                .append(error.getClass().getName());
        if (error.getMessage() != null) {
            line.append(": ").append(error.getMessage());
        }
        if (folded > 0) {
            line.append(" (").append(folded).append(folded == 1 ? " more fault" : " more faults")
                    .append(" since the previous line)");
        }
        out.println(line);
        folded = 0;
        pacer.printed(nowNs);
    }
}
