package io.rtaware.app.cli;

import io.rtaware.app.UserError;
import io.rtaware.app.output.OutputFile;
import io.rtaware.core.output.OutputWrites;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.trace.TraceRecorder;
import java.io.PrintStream;
import java.nio.file.Path;
import picocli.CommandLine.Option;

/**
 * {@code --trace FILE} and {@code --trace-capacity N}, shared by {@code run} and {@code bench}
 * (a picocli mixin): records the monitor's events into a bounded ring and writes a Chrome trace
 * event file that Perfetto opens.
 */
public final class TraceOptions {

    @Option(names = "--trace", paramLabel = "FILE",
            description = "Write a Chrome trace event file of every cycle; open it in ui.perfetto.dev.")
    Path file;

    @Option(names = "--trace-capacity", paramLabel = "N", defaultValue = "1048576",
            description = "Events kept by --trace; older ones are dropped and counted (default: ${DEFAULT-VALUE}).")
    int capacity;

    /**
     * Checks {@code --trace FILE} before the run starts, so a trace that cannot be written ends
     * the command at once instead of after the run.
     *
     * @throws UserError if the file cannot be written
     */
    public void checkOutput() {
        if (file != null) {
            OutputFile.of("--trace", file);
        }
    }

    /**
     * @return heap bytes the recorder will preallocate: 0 without {@code --trace}
     * @throws UserError if the capacity is not positive
     */
    public long heapBytes() {
        if (capacity < 1) {
            throw new UserError("--trace-capacity must be at least 1, got " + capacity);
        }
        return file == null ? 0 : MemoryBudget.times(capacity, TraceRecorder.BYTES_PER_EVENT);
    }

    /** @return the trace configuration in the user's words, for a refusal */
    public String describe() {
        return "--trace-capacity " + capacity + " (" + TraceRecorder.BYTES_PER_EVENT + " bytes per event)";
    }

    /**
     * Attaches a recorder if {@code --trace} was given; call before the monitor starts.
     *
     * @param monitor the built monitor
     * @return the recorder, or null without {@code --trace}
     * @throws UserError if the capacity is not positive
     */
    public TraceRecorder attach(Monitor monitor) {
        if (capacity < 1) {
            throw new UserError("--trace-capacity must be at least 1, got " + capacity);
        }
        return file == null ? null : TraceRecorder.attach(monitor, capacity);
    }

    /**
     * Writes the trace file and says where it went; a failure is reported and remembered by
     * {@code writes}, not thrown, so the rest of the termination goes on.
     *
     * @param recorder what {@link #attach} returned (null: nothing to do)
     * @param out where the confirmation goes
     * @param writes the command's writes (a failure makes its exit status non-zero)
     */
    public void write(TraceRecorder recorder, PrintStream out, OutputWrites writes) {
        if (recorder == null) {
            return;
        }
        if (writes.write(file, () -> recorder.write(file))) {
            out.println("trace written to " + file + " (" + recorder.recorded() + " events, "
                    + recorder.dropped() + " dropped; open it in https://ui.perfetto.dev)");
        }
    }
}
