package io.rtaware.app.output;

import io.rtaware.core.output.OutputFiles;

import io.rtaware.app.UserError;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Objects;

/**
 * An output folder named on the command line ({@code run --out}, {@code experiment --out},
 * {@code report DIR}), checked before the command runs, without creating anything: the name is
 * not empty (an empty {@code --out ""} would silently mean the current folder), it is not an
 * existing file, and a file can be made in it or, when it does not exist yet, in its nearest
 * existing ancestor (which must be a folder: a file in the way is named). The writer creates the
 * folder when it writes ({@link #create()}). A failure is a {@link UserError} naming the option,
 * the path and the reason. Immutable.
 */
public final class OutputFolder {

    private final String option;
    private final Path path;

    private OutputFolder(String option, Path path) {
        this.option = option;
        this.path = path;
    }

    /**
     * Checks that the folder exists and is writable, or can be created.
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
        if (Files.isDirectory(path)) {
            OutputFile.probe(option, path, what);
            return new OutputFolder(option, path);
        }
        Path ancestor = path.toAbsolutePath().getParent();
        while (ancestor != null && !Files.exists(ancestor)) {
            ancestor = ancestor.getParent();
        }
        if (ancestor == null) {
            throw new UserError(option + ": cannot create " + what + " " + path + ": no existing folder above it");
        }
        if (!Files.isDirectory(ancestor)) {
            throw new UserError(option + ": cannot create " + what + " " + path + ": a file is in the way (" + ancestor + ")");
        }
        try {
            Path probe = Files.createTempFile(ancestor, ".rtaware-write-check-", ".tmp");
            Files.delete(probe);
        } catch (IOException | SecurityException | UnsupportedOperationException e) {
            throw new UserError(option + ": cannot create " + what + " " + path + ": " + OutputFiles.reason(e));
        }
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

    /**
     * Creates the folder (and its parents) if it does not exist yet.
     *
     * @return the folder
     * @throws IOException if it cannot be created
     */
    public Path create() throws IOException {
        return Files.createDirectories(path);
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
