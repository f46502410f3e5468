package io.rtaware.app.output;

import io.rtaware.app.UserError;
import java.io.IOException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Objects;

/**
 * An output folder named on the command line ({@code run --out}, {@code experiment --out},
 * {@code report DIR}), checked before the command runs: the name is not empty (an empty
 * {@code --out ""} would silently mean the current folder), it is not an existing file, it is
 * created if missing, and a file can be made in it. A failure is a {@link UserError} naming the
 * option, the path and the reason. Immutable.
 */
public final class OutputFolder {

    private final String option;
    private final Path path;

    private OutputFolder(String option, Path path) {
        this.option = option;
        this.path = path;
    }

    /**
     * Checks the folder and creates it if missing.
     *
     * @param option the option that named it, e.g. {@code --out}
     * @param path the path given
     * @return the checked folder
     * @throws UserError if nothing can be written there
     */
    public static OutputFolder of(String option, Path path) {
        return of(option, path, "folder");
    }

    static OutputFolder of(String option, Path path, String what) {
        Objects.requireNonNull(option, "option");
        if (path == null || path.toString().isBlank()) {
            throw new UserError(option + " must name a folder, got an empty name");
        }
        if (Files.exists(path) && !Files.isDirectory(path)) {
            throw new UserError(option + " names an existing file, not a folder: " + path);
        }
        try {
            Files.createDirectories(path);
        } catch (FileAlreadyExistsException e) {
            throw new UserError(option + ": cannot create " + what + " " + path + ": a file is in the way ("
                    + e.getFile() + ")");
        } catch (IOException | SecurityException e) {
            throw new UserError(option + ": cannot create " + what + " " + path + ": " + OutputFile.reason(e));
        }
        OutputFile.probe(option, path, what);
        return new OutputFolder(option, path);
    }

    /**
     * Checks a folder that must already exist (e.g. {@code report DIR}, which reads from it).
     *
     * @param option what named it, e.g. {@code report}
     * @param path the path given
     * @return the checked folder
     * @throws UserError if it is missing, not a folder, or not writable
     */
    public static OutputFolder existing(String option, Path path) {
        if (path == null || path.toString().isBlank()) {
            throw new UserError(option + " must name a folder, got an empty name");
        }
        if (!Files.isDirectory(path)) {
            throw new UserError(option + ": " + path + " is not a folder");
        }
        OutputFile.probe(option, path, "folder");
        return new OutputFolder(option, path);
    }

    /** @return the folder as given */
    public Path path() {
        return path;
    }

    /**
     * @param name a file name inside the folder
     * @return its path
     */
    public Path resolve(String name) {
        return path.resolve(name);
    }

    /** @return the option that named it */
    public String option() {
        return option;
    }

    @Override
    public String toString() {
        return path.toString();
    }
}
