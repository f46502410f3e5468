package io.rtaware.core.log;

import java.io.PrintStream;
import java.util.Objects;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;

/**
 * Routes the log records of rtaware's libraries ({@link System.Logger}s named under
 * {@value #NAMESPACE}, which the JDK serves through java.util.logging) to one place, set once by
 * the program: records at or above a level become one plain line each on a stream (the message's
 * first line, as the library wrote it, e.g. {@code rtaware-sim: disconnecting client ...}); records
 * below it are dropped; nothing reaches java.util.logging's root console handler, whose two-line
 * records ({@code Nov 27, 2026 ... INFO: ...}) repeated what a command had already printed.
 *
 * <p>{@link #close()} restores the namespace's logger as it was. A program that configures
 * java.util.logging itself does not call this. Not thread-safe: install and close from one thread.
 */
public final class LibraryLog implements AutoCloseable {

    /** The namespace of every library logger. */
    public static final String NAMESPACE = "io.rtaware";

    private final Logger logger;
    private final Level savedLevel;
    private final boolean savedUseParentHandlers;
    private final Handler handler;

    private LibraryLog(Logger logger, Handler handler) {
        this.logger = logger;
        this.savedLevel = logger.getLevel();
        this.savedUseParentHandlers = logger.getUseParentHandlers();
        this.handler = handler;
    }

    /**
     * @param out where the lines go (standard error, for a command line)
     * @param lowest the lowest level printed (e.g. {@link System.Logger.Level#WARNING}: information
     *     that a command prints itself is not repeated)
     * @return the routing; close it to restore the logger
     */
    public static LibraryLog oneLineEach(PrintStream out, System.Logger.Level lowest) {
        Objects.requireNonNull(out, "out");
        Level level = julLevel(lowest);
        Logger logger = Logger.getLogger(NAMESPACE);
        Handler handler = new Handler() {
            @Override
            public void publish(LogRecord record) {
                if (record.getLevel().intValue() >= level.intValue()) {
                    String message = record.getMessage() == null ? "" : record.getMessage();
                    out.println(message.lines().findFirst().orElse(""));
                }
            }

            @Override
            public void flush() {
                out.flush();
            }

            @Override
            public void close() {
                flush();
            }
        };
        LibraryLog log = new LibraryLog(logger, handler);
        logger.setUseParentHandlers(false);
        logger.setLevel(level);
        logger.addHandler(handler);
        return log;
    }

    private static Level julLevel(System.Logger.Level level) {
        return switch (level) {
            case ALL -> Level.ALL;
            case TRACE -> Level.FINER;
            case DEBUG -> Level.FINE;
            case INFO -> Level.INFO;
            case WARNING -> Level.WARNING;
            case ERROR -> Level.SEVERE;
            case OFF -> Level.OFF;
        };
    }

    @Override
    public void close() {
        logger.removeHandler(handler);
        logger.setLevel(savedLevel);
        logger.setUseParentHandlers(savedUseParentHandlers);
    }
}
