package io.rtaware.app.output;

import io.rtaware.core.output.OutputWrites;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.app.CliRun;
import io.rtaware.app.UserError;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Objects;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Every output path is checked before anything runs; a write that fails later is named and makes the exit status non-zero. */
class OutputPathsTest {

    private static final Path DEV_FULL = Path.of("/dev/full");

    @TempDir
    Path dir;

    @Test
    void foldersAreCheckedBeforeAnythingRuns() throws IOException {
        Path file = Files.writeString(dir.resolve("a-file"), "x");
        assertTrue(assertThrows(UserError.class, () -> OutputFolder.of("--out", file)).getMessage()
                .contains("names an existing file, not a folder"));
        assertTrue(assertThrows(UserError.class, () -> OutputFolder.of("--out", Path.of(""))).getMessage()
                .contains("--out must name a folder, got an empty name"));
        assertTrue(assertThrows(UserError.class, () -> OutputFolder.of("--out", Path.of("/proc/rtaware-x"))).getMessage()
                .contains("cannot create folder /proc/rtaware-x"));
        assertTrue(assertThrows(UserError.class, () -> OutputFolder.of("--out", file.resolve("sub"))).getMessage()
                .contains("--out"), "a file in the way of the folder's path");
        OutputFolder later = OutputFolder.of("--out", dir.resolve("new/deep"));
        assertFalse(Files.exists(dir.resolve("new")), "checking creates nothing");
        assertTrue(Files.isDirectory(later.create()), "the writer creates it");
        try (var listing = Files.list(dir)) {
            assertEquals(2, listing.count(), "the write probe leaves nothing behind (a-file and new)");
        }
    }

    @Test
    void filesAreCheckedBeforeAnythingRuns() throws IOException {
        assertTrue(assertThrows(UserError.class, () -> OutputFile.of("--json", dir)).getMessage()
                .contains("--json names a folder, not a file"));
        assertTrue(assertThrows(UserError.class, () -> OutputFile.of("--json", Path.of(""))).getMessage()
                .contains("--json must name a file"));
        assertTrue(assertThrows(UserError.class, () -> OutputFile.of("--trace", Path.of("/proc/rtaware-x/t.json")))
                .getMessage().contains("--trace: cannot create"));
        assertEquals(dir.resolve("r.json"), OutputFile.of("--json", dir.resolve("r.json")).path());
        Files.writeString(dir.resolve("old.json"), "{}");
        OutputFile.of("--json", dir.resolve("old.json")); // an existing file is replaced
    }

    @Test
    void aFailedWriteIsNamedAndTheOthersAreStillWritten() {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        OutputWrites writes = new OutputWrites(new PrintStream(err, true, StandardCharsets.UTF_8));
        assertTrue(writes.write(dir.resolve("a"), () -> Files.writeString(dir.resolve("a"), "a")));
        assertFalse(writes.write(dir.resolve("b"), () -> {
            throw new IOException("No space left on device");
        }));
        assertTrue(writes.write(dir.resolve("c"), () -> Files.writeString(dir.resolve("c"), "c")));
        assertEquals(2, writes.written().size(), "the writes after a failure still happen");
        assertEquals("rtaware: could not write " + dir.resolve("b") + ": No space left on device",
                err.toString(StandardCharsets.UTF_8).strip());
        assertEquals(OutputWrites.EXIT_WRITE_FAILED, writes.exitStatus(0));
        assertEquals(130, writes.exitStatus(130), "an interrupted run keeps its status");
    }

    @Test
    void runRefusesBadOutputFoldersBeforeTheRun() throws IOException {
        Path file = Files.writeString(dir.resolve("taken"), "x");
        CliRun.of("run", "--out", file.toString(), "--quiet").assertOneLineUserError("names an existing file");
        CliRun.of("run", "--out", "", "--quiet").assertOneLineUserError("--out must name a folder, got an empty name");
        CliRun.of("run", "--out", "/proc/rtaware-x", "--quiet").assertOneLineUserError("cannot create folder /proc/rtaware-x");
        CliRun.of("run", "--out", dir.resolve("r").toString(), "--trace", dir.toString(), "--quiet")
                .assertOneLineUserError("--trace names a folder");
    }

    @Test
    void benchRefusesBadOutputFilesBeforeTheRun() {
        CliRun r = CliRun.of("bench", "--json", dir.toString(), "--duration", "1s");
        r.assertOneLineUserError("--json names a folder, not a file");
        assertFalse(r.out().contains("rtaware bench:"), "nothing ran: " + r.out());
        CliRun.of("bench", "--trace", "/proc/rtaware-x/t.json", "--duration", "1s").assertOneLineUserError("--trace: cannot create");
        CliRun.of("bench", "--json", "", "--duration", "1s").assertOneLineUserError("--json must name a file");
    }

    @Test
    void experimentAndReportRefuseBadFolders() throws IOException {
        Path file = Files.writeString(dir.resolve("taken"), "x");
        CliRun.of("experiment", "--out", file.toString()).assertOneLineUserError("names an existing file");
        CliRun.of("experiment", "--out", "").assertOneLineUserError("--out must name a folder");
        CliRun.of("experiment", "--out", "/proc/rtaware-x").assertOneLineUserError("cannot create folder");
        CliRun.of("report", file.toString()).assertOneLineUserError("is not a folder");
        CliRun.of("world", "--png", dir.toString()).assertOneLineUserError("--png names a folder, not a file");
    }

    @Test
    void benchJsonAndTraceOnAFullDiskAreErrorsAndTheSummaryIsStillPrinted() {
        org.junit.jupiter.api.Assumptions.assumeTrue(Files.exists(DEV_FULL), "/dev/full (a device whose writes fail with ENOSPC)");
        CliRun r = CliRun.of("bench", "--tasks", "1", "--period", "10ms", "--work", "0", "--duration", "200ms",
                "--quiet", "--json", DEV_FULL.toString(), "--trace", DEV_FULL.toString());
        assertEquals(OutputWrites.EXIT_WRITE_FAILED, r.status(), "a report that cannot be written is an error; " + r);
        assertTrue(r.err().contains("could not write /dev/full: No space left on device"), r.err());
        assertEquals(2, r.err().lines().filter(l -> l.contains("could not write")).count(), "the trace and the JSON: " + r.err());
        assertTrue(r.out().contains("rtaware summary"), "what could be written still is: " + r.out());
    }

    @Test
    void aRunWhoseFileCannotBeWrittenSaysSoAndWritesTheRest() throws Exception {
        org.junit.jupiter.api.Assumptions.assumeTrue(Files.exists(DEV_FULL), "/dev/full");
        Path scenario = Path.of(Objects.requireNonNull(getClass().getResource("/scenarios/short-leg.yaml")).toURI());
        Path out = Files.createDirectories(dir.resolve("run"));
        Files.createSymbolicLink(out.resolve("trajectory.csv"), DEV_FULL);
        CliRun r = CliRun.of("run", "--scenario", scenario.toString(), "--time-scale", "10", "--out", out.toString(),
                "--quiet", "--seed", "7");
        assertEquals(OutputWrites.EXIT_WRITE_FAILED, r.status(), r.toString());
        assertTrue(r.err().contains("could not write " + out.resolve("trajectory.csv") + ": No space left on device"), r.err());
        for (String file : new String[] {"report.json", "report.md", "trajectory.png", "map.pgm"}) {
            assertTrue(Files.size(out.resolve(file)) > 0, file + " is still written");
        }
    }
}
