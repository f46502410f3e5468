package io.rtaware.app.cli;

import io.rtaware.app.UserError;
import io.rtaware.core.monitor.ConfigurationException;
import io.rtaware.core.conditions.ConditionsMeter;
import io.rtaware.core.monitor.ConsoleReporter;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.task.Schedule;
import io.rtaware.live.LiveView;
import java.io.PrintStream;
import java.util.function.Supplier;

/**
 * The parts of a monitor's life that every command running tasks shares ({@code run},
 * {@code bench}): building with configuration errors turned into one-line user errors, the live
 * console, the machine verdict shown live, and stopping with the shutdown hook removed.
 */
public final class CommandMonitor {

    private CommandMonitor() {
    }

    /**
     * @param builder the configured builder
     * @return the initialized monitor
     * @throws UserError listing every configuration violation on one line
     */
    public static Monitor build(Monitor.Builder builder) {
        try {
            return builder.build();
        } catch (ConfigurationException e) {
            throw new UserError(String.join("; ", e.violations()));
        }
    }

    /**
     * Attaches the rate-limited live console unless the user asked for quiet; before the start.
     *
     * @param monitor the built monitor
     * @param quiet true for no live lines
     * @param err where the lines go
     * @return the reporter (close it in the termination handler), or null when quiet
     */
    public static ConsoleReporter console(Monitor monitor, boolean quiet, PrintStream err) {
        if (quiet) {
            return null;
        }
        ConsoleReporter console = new ConsoleReporter(err, monitor.tasks(), false);
        monitor.addListener(console);
        return console;
    }

    /**
     * Stops the monitor (the termination handlers run) and removes the shutdown hook that would
     * otherwise stop it again at exit.
     *
     * @param monitor the running monitor
     * @param hook what {@link Monitor#installShutdownHook()} returned
     */
    public static void stop(Monitor monitor, Thread hook) {
        monitor.stop();
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException shuttingDown) {
            // The JVM is already exiting: the hook is doing, or has done, the same work.
        }
    }

    /**
     * Shows the run's machine verdict so far in the live view's header, judged as the report's
     * is, against the monitor's shortest period.
     *
     * @param live the live view
     * @param monitor the monitor whose periods the pauses are judged against
     * @param span the measurement under way, or null until it starts
     */
    public static void showMachine(LiveView live, Monitor monitor, Supplier<ConditionsMeter.Span> span) {
        double shortestMs = monitor.tasks().stream().map(t -> t.schedule())
                .filter(s -> s instanceof Schedule.Periodic).mapToDouble(s -> ((Schedule.Periodic) s).periodNs() / 1e6)
                .min().orElse(Double.NaN);
        live.machine(() -> {
            ConditionsMeter.Span s = span.get();
            return s == null ? null : s.sofar(shortestMs);
        });
    }
}
