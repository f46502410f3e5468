package io.rtaware.app.output;

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

/** Issue 24: writes to {@code --out} go to a temporary name and are renamed when complete. */
class OutputWritesTest {

    @TempDir
    Path dir;

    private final ByteArrayOutputStream err = new ByteArrayOutputStream();
    private final OutputWrites writes = new OutputWrites(new PrintStream(err, true, StandardCharsets.UTF_8));

    @Test
    void aCompleteWriteAppearsUnderItsNameAndLeavesNoTemporaryFile() throws IOException {
        Path file = dir.resolve("report.json");
        assertTrue(writes.writeFile(file, target -> {
            assertEquals(dir.resolve(".report.partial.json"), target, "written under a temporary name first");
            assertFalse(Files.exists(file), "the file appears only once complete");
            Files.writeString(target, "{}");
        }));
        assertEquals("{}", Files.readString(file));
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(1, files.count(), "no temporary file left");
        }
        assertEquals(0, writes.exitStatus(0));
    }

    @Test
    void aFailedWriteKeepsTheOlderFileWholeAndRemovesTheHalfWrittenOne() throws IOException {
        Path file = Files.writeString(dir.resolve("report.md"), "the previous report");
        assertFalse(writes.writeFile(file, target -> {
            Files.writeString(target, "half of a new rep");
            throw new IOException("No space left on device");
        }));
        assertEquals("the previous report", Files.readString(file), "the older file is untouched");
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(1, files.count(), "the half-written temporary file is removed");
        }
        assertTrue(err.toString(StandardCharsets.UTF_8).contains("could not write " + file + ": No space left on device"));
        assertEquals(OutputWrites.EXIT_WRITE_FAILED, writes.exitStatus(0));
    }

    @Test
    void aLinkIsWrittenThroughNotReplaced() throws IOException {
        Path real = Files.writeString(dir.resolve("real.csv"), "old");
        Path link = Files.createSymbolicLink(dir.resolve("trajectory.csv"), real);
        assertTrue(writes.writeFile(link, target -> Files.writeString(target, "new")));
        assertTrue(Files.isSymbolicLink(link), "the link stays a link");
        assertEquals("new", Files.readString(real));
    }
}
