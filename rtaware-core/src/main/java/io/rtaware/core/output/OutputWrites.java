package io.rtaware.core.output;

import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.function.Consumer;

/**
 * The writes of one command's outputs, each on its own: a write that fails (a full disk, a file
 * replaced by a folder meanwhile) is printed as one line naming the file and the reason, is
 * remembered, and does not stop the others, so what can still be written is. The command then
 * ends with {@link #exitStatus(int)}. Not thread-safe; use it from one thread (e.g. a
 * termination handler).
 */
public final class OutputWrites {

    /** Exit status of a command whose work finished but some output could not be written. */
    public static final int EXIT_WRITE_FAILED = 1;

    /** A write of one file. */
    @FunctionalInterface
    public interface Write {
        /**
         * @throws IOException if writing fails
         */
        void run() throws IOException;
    }

    private final PrintStream err;
    private final List<Path> written = new ArrayList<>();
    private final List<String> failures = new ArrayList<>();

    /** @param err where a failure's line goes */
    public OutputWrites(PrintStream err) {
        this.err = err;
    }

    /**
     * @param file the file written (named in a failure)
     * @param write what writes it
     * @return true if it was written
     */
    public boolean write(Path file, Write write) {
        try {
            write.run();
            written.add(file);
            return true;
        } catch (IOException | UncheckedIOException | SecurityException e) {
            Exception cause = e instanceof UncheckedIOException u ? u.getCause() : e;
            String line = "could not write " + file + ": " + OutputFiles.reason(cause);
            failures.add(line);
            err.println("rtaware: " + line);
            err.flush();
            return false;
        }
    }

    /**
     * Writes a file through {@link OutputFiles#write}: a regular file whole or not at all (a
     * temporary name beside it, renamed once complete; after a failure an older version stays as
     * it was and nothing half-written is left), a pipe or a character device (e.g.
     * {@code /dev/stdout}, {@code /dev/null}) in place, never deleted or replaced; a folder, a
     * socket or a block device is refused. A failure is reported as by {@link #write}.
     *
     * @param file the file to write
     * @param content its content
     * @return true if the file was written
     */
    public boolean writeFile(Path file, OutputFiles.Content content) {
        return write(file, () -> OutputFiles.write(file, content));
    }

    /**
     * Counts a failure found elsewhere (e.g. a recording that could not be completed) as a
     * failed write: prints its line and makes the exit status say so.
     *
     * @param line what failed and why, naming the file
     */
    public void failed(String line) {
        failures.add(line);
        err.println("rtaware: " + line);
        err.flush();
    }

    /**
     * Remembers a step of the command's output that failed for a reason other than a write (a
     * bug in what computes an output), so that the command does not end with status 0: prints one
     * line naming the step and the error, then the error's stack trace, which a maintainer needs.
     *
     * @param step what could not be done, e.g. {@code analyze the run}
     * @param error why
     */
    public void failed(String step, Throwable error) {
        failed("could not " + step + ": " + error);
        error.printStackTrace(err);
        err.flush();
    }

    /**
     * Wraps a step that ends a command's outputs (e.g. the monitor's termination handler that
     * prints the summary and writes the report): whatever it throws, a bug or an
     * {@link OutOfMemoryError} while the report is written, is {@link #failed(String, Throwable)
     * a failed step}, so the command does not end with status 0 as if its outputs were complete.
     *
     * @param step what the action does, for the failure's line, e.g. {@code finish the run's report}
     * @param action the step
     * @param <T> what the step is given
     * @return the step, guarded
     */
    public <T> Consumer<T> guarding(String step, Consumer<T> action) {
        return value -> {
            try {
                action.accept(value);
            } catch (RuntimeException | Error e) {
                failed(step, e);
            }
        };
    }

    /** @return the files written, in order */
    public List<Path> written() {
        return Collections.unmodifiableList(written);
    }

    /** @return one line per failed write */
    public List<String> failures() {
        return Collections.unmodifiableList(failures);
    }

    /** @return true if any write failed */
    public boolean failed() {
        return !failures.isEmpty();
    }

    /**
     * @param status the command's status from its own work
     * @return that status, or {@link #EXIT_WRITE_FAILED} if it was 0 and a write failed
     */
    public int exitStatus(int status) {
        return status == 0 && failed() ? EXIT_WRITE_FAILED : status;
    }
}
