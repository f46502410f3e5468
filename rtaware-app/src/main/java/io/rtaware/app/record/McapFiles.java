package io.rtaware.app.record;

import io.rtaware.app.UserError;
import io.rtaware.record.mcap.McapFormatException;
import java.io.IOException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;

/** What the commands that open a recording ({@code inspect}, {@code replay}) tell the user when they cannot. */
public final class McapFiles {

    private McapFiles() {
    }

    /**
     * @param file the recording
     * @param e why it could not be opened or read
     * @return the one line for the user: a missing file, the format problem as the reader names
     *     it, or the I/O error
     */
    public static UserError unreadable(Path file, IOException e) {
        if (e instanceof NoSuchFileException) {
            return new UserError("no such file: " + file);
        }
        if (e instanceof McapFormatException) {
            return new UserError(e.getMessage());
        }
        return new UserError("cannot read " + file + ": " + e.getMessage());
    }
}
