package io.rtaware.experiment;

import java.io.IOException;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/** Reads the experiment's text files, refusing one that is not UTF-8 in the user's one line. */
final class Utf8Text {

    private Utf8Text() {
    }

    /**
     * @param file the file
     * @param what what the file should be, for the message (e.g. {@code results file})
     * @return its text
     * @throws IOException if it cannot be read
     * @throws ExperimentInputException if its bytes are not UTF-8 (found by fuzzing: the decoder's
     *     exception escaped as a stack trace)
     */
    static String read(Path file, String what) throws IOException {
        try {
            return Files.readString(file, StandardCharsets.UTF_8);
        } catch (CharacterCodingException e) {
            throw new ExperimentInputException(what + " " + file + " is not UTF-8 text");
        }
    }
}
