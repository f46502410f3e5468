package io.rtaware.core.output;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 24: writes to {@code --out} go to a temporary name and are renamed when complete
 * ({@code OutputFilesTest} in the core has the cases); a failure is one line and the exit status.
 */
class OutputWritesTest {

    @TempDir
    Path dir;

    private final ByteArrayOutputStream err = new ByteArrayOutputStream();
    private final OutputWrites writes = new OutputWrites(new PrintStream(err, true, StandardCharsets.UTF_8));

    @Test
    void aCompleteWriteIsRememberedAndTheStatusStaysZero() throws IOException {
        Path file = dir.resolve("report.json");
        assertTrue(writes.writeFile(file, OutputFiles.text("{}")));
        assertEquals("{}", Files.readString(file));
        assertEquals(java.util.List.of(file), writes.written());
        assertEquals(0, writes.exitStatus(0));
    }

    @Test
    void aFailedWriteIsOneLineKeepsTheOlderFileAndSetsTheStatus() throws IOException {
        Path file = Files.writeString(dir.resolve("report.md"), "the previous report");
        assertFalse(writes.writeFile(file, out -> {
            out.write("half of a new rep".getBytes(StandardCharsets.UTF_8));
            throw new IOException("No space left on device");
        }));
        assertEquals("the previous report", Files.readString(file), "the older file is untouched");
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(1, files.count(), "the half-written temporary file is removed");
        }
        assertEquals("rtaware: could not write " + file + ": No space left on device",
                err.toString(StandardCharsets.UTF_8).strip());
        assertEquals(OutputWrites.EXIT_WRITE_FAILED, writes.exitStatus(0));
    }

    /**
     * Issue 36: bench's termination handler ran its report unguarded, so an OutOfMemoryError while
     * report.json was written ended the command with status 0; run's guarded it by hand.
     */
    @Test
    void aGuardedStepThatThrowsIsAFailedStepAndSetsTheStatus() {
        writes.guarding("finish the run's report", report -> {
            throw new OutOfMemoryError("Java heap space");
        }).accept("the report");

        assertEquals(1, writes.exitStatus(0));
        assertTrue(err.toString(StandardCharsets.UTF_8).startsWith(
                "rtaware: could not finish the run's report: java.lang.OutOfMemoryError: Java heap space"), err.toString());
    }

    @Test
    void aGuardedStepThatEndsWellKeepsTheStatus() {
        StringBuilder seen = new StringBuilder();
        writes.guarding("finish the run's report", seen::append).accept("the report");

        assertEquals("the report", seen.toString());
        assertEquals(0, writes.exitStatus(0));
    }
}
