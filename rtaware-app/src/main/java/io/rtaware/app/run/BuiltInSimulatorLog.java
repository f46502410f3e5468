package io.rtaware.app.run;

import java.io.PrintStream;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;

/**
 * While {@code run} drives the built-in simulator, the simulator's log (java.util.logging under
 * {@code io.rtaware.sim}) does not reach the console in JUL's two-line format: its INFO lines
 * ("serving Player on ...", "client lost") are dropped, and a WARNING or worse is printed as
 * the one plain line it is. {@link #close()} restores the logger as it was. The simulator served
 * alone ({@code rtaware sim}) keeps its normal log.
 */
final class BuiltInSimulatorLog implements AutoCloseable {

    /** The simulator's logger namespace. */
    static final String LOGGER = "io.rtaware.sim";

    private final Logger logger;
    private final Level level;
    private final boolean useParentHandlers;
    private final Handler handler;

    private BuiltInSimulatorLog(Logger logger, Handler handler) {
        this.logger = logger;
        this.level = logger.getLevel();
        this.useParentHandlers = logger.getUseParentHandlers();
        this.handler = handler;
    }

    /**
     * @param err where warnings go
     * @return the installed redirection; close it when the simulator is closed
     */
    static BuiltInSimulatorLog install(PrintStream err) {
        Logger logger = Logger.getLogger(LOGGER);
        Handler handler = new Handler() {
            @Override
            public void publish(LogRecord record) {
                if (record.getLevel().intValue() >= Level.WARNING.intValue() && record.getMessage() != null) {
                    err.println(record.getMessage().lines().findFirst().orElse(""));
                }
            }

            @Override
            public void flush() {
                err.flush();
            }

            @Override
            public void close() {
                flush();
            }
        };
        BuiltInSimulatorLog log = new BuiltInSimulatorLog(logger, handler);
        logger.setUseParentHandlers(false);
        logger.setLevel(Level.WARNING);
        logger.addHandler(handler);
        return log;
    }

    @Override
    public void close() {
        logger.removeHandler(handler);
        logger.setLevel(level);
        logger.setUseParentHandlers(useParentHandlers);
    }
}
