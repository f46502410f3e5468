package io.rtaware.record.mcap;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;

/**
 * Coverage-guided fuzzing of the MCAP reader with the bytes of a file (issue 24: 31 of 408 fuzzed
 * files printed stack traces in {@code inspect}): opened as a finished file and as an unfinished
 * one, read through every record, summarized and recovered. A file that is not a good MCAP file
 * may only be refused with a {@link McapFormatException} (the user's one line); any other
 * throwable is a finding. Without {@code JAZZER_FUZZ=1} it replays the corpus in
 * {@code McapReaderFuzzTestInputs/}, seeded with a real bench recording, the same cut short, and a
 * minimal file.
 */
class McapReaderFuzzTest {

    private static Path file;
    private static long sink;

    /** Reads every field of every record the reader hands out. */
    private static final McapVisitor EVERYTHING = new McapVisitor() {
        @Override
        public void metadata(String name, Map<String, String> entries) {
            entries.forEach((k, v) -> k.length());
        }

        @Override
        public void message(McapChannel channel, long sequence, long logTimeNs, long publishTimeNs, byte[] data,
                            int offset, int length) {
            for (int i = offset; i < offset + length; i++) {
                sink += data[i];
            }
        }
    };

    @BeforeAll
    static void folder() throws IOException {
        file = Files.createTempDirectory("mcap-fuzz").resolve("input.mcap");
    }

    @AfterAll
    static void removeFolder() throws IOException {
        Files.deleteIfExists(file);
        Files.delete(file.getParent());
    }

    @FuzzTest(maxDuration = "20s")
    void readingAFileThrowsNothingButFormatErrors(byte[] input) throws IOException {
        Files.write(file, input);
        try {
            McapReader finished = McapReader.open(file);
            finished.read(EVERYTHING);
            finished.summary();
            finished.profile();
        } catch (McapFormatException refused) {
            // the user's one line
        }
        try {
            McapReader.openUnfinished(file).readRecoverable(EVERYTHING);
        } catch (McapFormatException refused) {
            // the user's one line
        }
    }
}
