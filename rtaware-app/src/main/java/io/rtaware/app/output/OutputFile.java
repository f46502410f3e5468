package io.rtaware.app.output;

import io.rtaware.app.UserError;
import io.rtaware.core.output.OutputFiles;
import java.io.IOException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Objects;

/**
 * One output file named on the command line ({@code --json FILE}, {@code --trace FILE}, and any
 * later option such as {@code --record FILE.mcap}), checked before the command runs, without
 * creating anything: the name is not empty, it is not a folder, its folder accepts a new file (or
 * can be created, see {@link OutputFolder}), and an existing file is writable. What may stand at
 * the path is what {@link OutputFiles} writes: a regular file (replaced whole once the new one is
 * complete), a pipe or a character device such as {@code /dev/null} (written in place); a socket or
 * a block device is refused. A failure is a {@link UserError} naming the option, the
 * path and the reason. Immutable.
 */
public final class OutputFile {

    private final String option;
    private final Path path;

    private OutputFile(String option, Path path) {
        this.option = option;
        this.path = path;
    }

    /**
     * @param option the option that named the file, e.g. {@code --json}
     * @param path the path given
     * @return the checked file
     * @throws UserError if the file cannot be written
     */
    public static OutputFile of(String option, Path path) {
        Objects.requireNonNull(option, "option");
        if (path == null || path.toString().isBlank()) {
            throw new UserError(option + " must name a file, got an empty name");
        }
        if (Files.isDirectory(path)) {
            throw new UserError(option + " names a folder, not a file: " + path);
        }
        Path parent = path.toAbsolutePath().getParent();
        if (parent != null) {
            OutputFolder.of(option, parent, "the folder of " + path);
        }
        try {
            OutputFiles.refusal(path).ifPresent(what -> {
                throw new UserError(option + ": " + path + " is " + what);
            });
        } catch (IOException e) {
            throw new UserError(option + ": cannot write " + path + ": " + OutputFiles.reason(e));
        }
        if (Files.exists(path) && !Files.isWritable(path)) {
            throw new UserError(option + ": cannot write " + path + ": permission denied");
        }
        return new OutputFile(option, path);
    }

    /** @return the path as given */
    public Path path() {
        return path;
    }

    /** @return the option that named it */
    public String option() {
        return option;
    }

    @Override
    public String toString() {
        return path.toString();
    }

    /** Probes a folder: creates a file in it and deletes it again. */
    static void probe(String option, Path dir, String what) {
        try {
            Path probe = Files.createTempFile(dir, ".rtaware-write-check-", ".tmp");
            Files.delete(probe);
        } catch (IOException | SecurityException | UnsupportedOperationException e) {
            throw new UserError(option + ": cannot write into " + what + " (" + dir + "): " + OutputFiles.reason(e));
        }
    }

}
