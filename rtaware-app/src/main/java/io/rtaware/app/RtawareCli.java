package io.rtaware.app;

import io.rtaware.app.analyze.AnalyzeCommand;
import io.rtaware.app.bench.BenchCommand;
import io.rtaware.app.experiment.ExperimentCommand;
import io.rtaware.app.experiment.ReportCommand;
import io.rtaware.app.player.PlayerProbeCommand;
import io.rtaware.app.record.InspectCommand;
import io.rtaware.app.replay.ReplayCommand;
import io.rtaware.app.run.RunCommand;
import io.rtaware.app.sim.SimCommand;
import io.rtaware.app.sim.WorldCommand;
import io.rtaware.core.log.LibraryLog;
import io.rtaware.core.text.NearestName;
import java.io.PrintWriter;
import java.nio.file.InvalidPathException;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * The {@code rtaware} command: entry point and composition root. User errors end with one line
 * and exit status 2; the system's refusal of another thread ends with one line and status 1;
 * anything else is a bug and shows its stack trace with status 1. The libraries' warnings are
 * one line each on stderr ({@link LibraryLog}), set here once.
 */
@Command(name = "rtaware", mixinStandardHelpOptions = true, version = "rtaware 0.1.0",
        description = "Run robot controllers whose tasks are aware of time.",
        footer = {"", "JVM: unless RTAWARE_JAVA_OPTS is set (it replaces them), the ./rtaware launcher runs Java with "
                + "-XX:+UseZGC -Xms512m -Xmx512m -XX:+AlwaysPreTouch, plus on JDK 21-23 -XX:+ZGenerational, and on JDK "
                + "17.0.8 and later, 21 and 22 no guaranteed safepoint every second. ZGC is the measured choice: G1 pauses "
                + "of 15-28 ms under garbage load go straight into release lateness (docs/performance.md, JVM choice: "
                + "rtaware bench --compare --gc-pressure 200)."},
        subcommands = {RunCommand.class, SimCommand.class, WorldCommand.class, BenchCommand.class, AnalyzeCommand.class,
                ExperimentCommand.class, ReportCommand.class, PlayerProbeCommand.class, InspectCommand.class, ReplayCommand.class,
                CommandLine.HelpCommand.class})
public final class RtawareCli {

    /** Exit status for a mistake in the user's input. */
    public static final int EXIT_USER_ERROR = 2;

    private RtawareCli() {
    }

    /**
     * @param args command-line arguments
     */
    public static void main(String[] args) {
        System.exit(execute(args));
    }

    /**
     * Runs one command line without exiting the JVM.
     *
     * @param args command-line arguments
     * @return the exit status
     */
    public static int execute(String... args) {
        return execute(CommandLine.defaultFactory(), args);
    }

    /**
     * Runs one command line without exiting the JVM, with the commands made by a factory (e.g. a
     * command given a smaller memory budget than this JVM's).
     *
     * @param factory makes the command objects
     * @param args command-line arguments
     * @return the exit status
     */
    public static int execute(CommandLine.IFactory factory, String... args) {
        // The libraries' log (the simulator's "serving Player on ...", "client lost") repeated what the
        // commands print, in java.util.logging's two-line records: warnings are one line on stderr, the rest dropped.
        try (LibraryLog log = LibraryLog.oneLineEach(System.err, System.Logger.Level.WARNING)) {
            CommandLine cli = commandLine(factory);
            try {
                return cli.execute(args); // picocli hands Exceptions to the handlers above, not Errors
            } catch (OutOfMemoryError e) {
                if (!String.valueOf(e.getMessage()).startsWith("unable to create native thread")) {
                    throw e;
                }
                // the system's limit on threads, met while starting tasks, workers or a server's loops
                cli.getErr().println("rtaware: the system refused another thread (" + e.getMessage() + "); run fewer "
                        + "tasks or --workers, or raise the limit on threads (ulimit -u, pid_max, a container's pids limit)");
                return 1;
            }
        }
    }

    /**
     * The {@code rtaware} command line with its error handling, not yet run (tests read its model:
     * options, help).
     *
     * @param factory makes the command objects
     * @return the command line
     */
    public static CommandLine commandLine(CommandLine.IFactory factory) {
        CommandLine cli = new CommandLine(new RtawareCli(), factory);
        // "Usage: rtaware run [OPTIONS]": the options are listed one per line below; a synopsis of
        // thirty of them wrapped mid-option ("[--export-zenoh=tcp/HOST:" / "PORT]")
        cli.getCommandSpec().usageMessage().abbreviateSynopsis(true);
        cli.getSubcommands().values().forEach(c -> c.getCommandSpec().usageMessage().abbreviateSynopsis(true));
        cli.setParameterExceptionHandler((ex, a) -> {
            PrintWriter err = ex.getCommandLine().getErr();
            String suggestion = ex instanceof CommandLine.UnmatchedArgumentException u && !u.getUnmatched().isEmpty()
                    ? NearestName.suggestion(u.getUnmatched().get(0).split("=", 2)[0], u.getSuggestions()) : "";
            err.println("rtaware: " + ex.getMessage().lines().findFirst().orElse("invalid arguments") + suggestion
                    + " (see: " + ex.getCommandLine().getCommandSpec().qualifiedName() + " --help)");
            return EXIT_USER_ERROR;
        });
        cli.setExecutionExceptionHandler((ex, cmd, parseResult) -> {
            if (ex instanceof UserError) {
                cmd.getErr().println("rtaware: " + ex.getMessage());
                return EXIT_USER_ERROR;
            }
            if (ex instanceof InvalidPathException e) {
                cmd.getErr().println("rtaware: '" + e.getInput() + "' is not a file name this system can use ("
                        + e.getReason() + "); with LC_ALL=C only ASCII names work: use a UTF-8 locale (LC_ALL=C.UTF-8)");
                return EXIT_USER_ERROR;
            }
            throw ex;
        });
        return cli;
    }
}
