package io.rtaware.app.cli;

import io.rtaware.app.UserError;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.record.RecordingListener;
import io.rtaware.record.RecordingPlan;
import io.rtaware.record.RecordingStats;
import io.rtaware.record.RunRecorder;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import picocli.CommandLine.Option;

/**
 * {@code --record FILE.mcap}, shared by {@code run}, {@code bench} and {@code experiment} (a
 * picocli mixin): records the run to an MCAP file (every commit, every cycle, the monitor's
 * events). Without the flag nothing is created and nothing is attached.
 */
public final class RecordOptions {

    @Option(names = "--record", paramLabel = "FILE.mcap",
            description = "Record the run to an MCAP file (open it in Foxglove; replay it with rtaware replay).")
    Path file;

    /** @return true if {@code --record} was given */
    public boolean enabled() {
        return file != null;
    }

    /** @return the file, or null */
    public Path file() {
        return file;
    }

    /**
     * Creates the recording and attaches it to the monitor, if {@code --record} was given.
     *
     * @param monitor a monitor that has not started
     * @param plan topics and metadata
     * @return the recorder, or null without {@code --record}
     * @throws UserError if the file cannot be created
     */
    public RunRecorder attach(Monitor monitor, RecordingPlan plan) {
        return file == null ? null : attach(monitor, file, plan);
    }

    /**
     * Creates a recording in a given file (an experiment's run folder).
     *
     * @param monitor a monitor that has not started
     * @param target the file
     * @param plan topics and metadata
     * @return the recorder
     * @throws UserError if the file cannot be created
     */
    public static RunRecorder attach(Monitor monitor, Path target, RecordingPlan plan) {
        try {
            Path parent = target.toAbsolutePath().getParent();
            if (parent != null) {
                Files.createDirectories(parent);
            }
            return RecordingListener.attach(monitor, target, plan);
        } catch (IOException e) {
            throw new UserError("--record: cannot write " + target + ": " + e.getMessage());
        }
    }

    /**
     * Finishes the file (summary and footer) and says what it holds. Failures are reported, not
     * thrown, so the rest of the termination goes on.
     *
     * @param recorder what {@link #attach} returned (null: nothing to do)
     * @param out where the confirmation goes
     * @param err where a failure goes
     * @return the recording's statistics, or null without a recorder
     */
    public static RecordingStats finish(RunRecorder recorder, PrintStream out, PrintStream err) {
        if (recorder == null) {
            return null;
        }
        RecordingStats stats = recorder.finish();
        if (stats.error() != null) {
            err.println("rtaware: recording " + stats.file() + " incomplete: " + stats.error());
        }
        out.printf("recording written to %s (%d messages, %d bytes, %d dropped; open it in Foxglove or "
                + "rtaware inspect)%n", stats.file(), stats.messages(), stats.bytes(), stats.dropped());
        return stats;
    }
}
