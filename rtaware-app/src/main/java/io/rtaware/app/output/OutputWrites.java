package io.rtaware.app.output;

import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

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

    /** A write of one file's content to the path it is given (a temporary name beside the file). */
    @FunctionalInterface
    public interface FileWrite {
        /**
         * @param target where to write the content
         * @throws IOException if writing fails
         */
        void to(Path target) throws IOException;
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
            String line = "could not write " + file + ": " + OutputFile.reason(cause);
            failures.add(line);
            err.println("rtaware: " + line);
            err.flush();
            return false;
        }
    }

    /**
     * Writes a file under a temporary name in its folder ({@code .NAME.partial.EXT}, so that a
     * writer that appends the extension keeps it) and renames it to its name once complete, so
     * the file is either whole or, after a failed or interrupted write, absent (an older version
     * stays as it was). A name that is a link or a device (e.g. {@code /dev/full},
     * {@code /dev/null}) is written in place: the user chose what stands there, and a rename
     * would replace it. A failure deletes the temporary file and is reported as by {@link #write}.
     *
     * @param file the file to write
     * @param write writes the content to the path it is given
     * @return true if the file was written (and renamed)
     */
    public boolean writeFile(Path file, FileWrite write) {
        boolean replaceable = !Files.exists(file, LinkOption.NOFOLLOW_LINKS)
                || Files.isRegularFile(file, LinkOption.NOFOLLOW_LINKS);
        if (!replaceable) {
            return write(file, () -> write.to(file));
        }
        Path temporary = partialName(file);
        return write(file, () -> {
            try {
                write.to(temporary);
                Files.move(temporary, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
            } finally {
                Files.deleteIfExists(temporary);
            }
        });
    }

    /**
     * @param file a file
     * @return the temporary name {@link #writeFile} writes it under
     */
    public static Path partialName(Path file) {
        String name = file.getFileName().toString();
        int dot = name.lastIndexOf('.');
        String partial = dot > 0 ? "." + name.substring(0, dot) + ".partial" + name.substring(dot)
                : "." + name + ".partial";
        return file.resolveSibling(partial);
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
