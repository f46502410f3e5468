package io.rtaware.app.cli;

import io.rtaware.app.UserError;
import io.rtaware.app.output.OutputFile;
import io.rtaware.core.output.OutputWrites;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.record.RecordingListener;
import io.rtaware.record.RecordingPlan;
import io.rtaware.record.RecordingStats;
import io.rtaware.record.RunRecorder;
import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.Locale;
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

    @Option(names = "--overwrite",
            description = "Replace the --record file if it exists (without it, an existing file is refused).")
    boolean overwrite;

    /** @return true if {@code --record} was given */
    public boolean enabled() {
        return file != null;
    }

    /** @return the file, or null */
    public Path file() {
        return file;
    }

    /**
     * Checks {@code --record FILE} before the run starts: a name, not a folder, a folder that
     * accepts the file, and no existing file unless {@code --overwrite} (a recording is never
     * replaced silently).
     *
     * @throws UserError if the file cannot or must not be written
     */
    public void checkOutput() {
        if (file == null) {
            return;
        }
        OutputFile.of("--record", file);
        if (Files.exists(file, LinkOption.NOFOLLOW_LINKS) && !overwrite) {
            throw new UserError("--record: " + file + " exists; give --overwrite to replace it");
        }
    }

    /**
     * Creates the recording and attaches it to the monitor, if {@code --record} was given or the
     * plan has a tap ({@code --foxglove}: then, without {@code --record}, a recorder without a
     * file feeds the tap alone).
     *
     * @param monitor a monitor that has not started
     * @param plan topics and metadata
     * @return the recorder, or null without {@code --record} and without a tap
     * @throws UserError if the file cannot be created
     */
    public RunRecorder attach(Monitor monitor, RecordingPlan plan) {
        checkOutput();
        if (file != null) {
            return attach(monitor, file, plan);
        }
        if (plan.tap() == null) {
            return null;
        }
        try {
            return RecordingListener.attach(monitor, null, plan);
        } catch (IOException e) {
            throw new UncheckedIOException("a recorder without a file writes nothing, yet failed", e);
        }
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
     * Finishes the file (summary and footer) and says what it holds. A recording that could not
     * be completed (a full disk) is not called written: one line says it is incomplete, why, and
     * what it holds, and counts as a failed write (the command's exit status 1). Nothing is
     * thrown, so the rest of the termination goes on.
     *
     * @param recorder what {@link #attach} returned (null: nothing to do; one without a file is
     *     finished, and nothing is said)
     * @param out where the confirmation goes
     * @param writes the command's writes, told of an incomplete recording
     * @return the recording's statistics, or null without a recorder or a file
     */
    public static RecordingStats finish(RunRecorder recorder, PrintStream out, OutputWrites writes) {
        if (recorder == null) {
            return null;
        }
        RecordingStats stats = recorder.finish();
        if (recorder.file() == null) {
            return null; // a recorder for --foxglove alone: no file to speak of
        }
        if (stats.error() != null) {
            writes.failed(String.format(Locale.ROOT, "recording %s is incomplete: %s; it holds %d messages in whole "
                    + "chunks (%d bytes written, %d records dropped); 'rtaware inspect --recover %s' writes them to a "
                    + "valid file", stats.file(), stats.error(), stats.messages(), stats.bytes(), stats.dropped(),
                    stats.file()));
            return stats;
        }
        out.printf(Locale.ROOT, "recording written to %s (%d messages, %d bytes, %d dropped%s; open it in Foxglove or "
                + "rtaware inspect)%n", stats.file(), stats.messages(), stats.bytes(), stats.dropped(),
                stats.outOfOrder() == 0 ? "" : ", " + stats.outOfOrder() + " written out of log-time order");
        return stats;
    }
}
