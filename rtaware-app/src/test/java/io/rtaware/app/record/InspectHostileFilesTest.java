package io.rtaware.app.record;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import io.rtaware.app.CliRun;
import io.rtaware.record.mcap.Compression;
import io.rtaware.record.mcap.McapWriter;
import java.io.IOException;
import java.io.RandomAccessFile;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code rtaware inspect} on the files of issue 24's finding 4 (and what blocked it): one line,
 * exit status 2, never a stack trace.
 */
class InspectHostileFilesTest {

    @TempDir
    Path dir;

    private Path recording() throws IOException {
        Path file = dir.resolve("small.mcap");
        try (McapWriter w = new McapWriter(file, Compression.ZSTD, 2048, "")) {
            int schema = w.addSchema("test/Thing", "jsonschema", "{}");
            int channel = w.addChannel(schema, "/a", "json", Map.of());
            for (int i = 0; i < 300; i++) {
                byte[] p = ("{\"i\":" + i + ",\"pad\":\"" + "z".repeat(i % 30) + "\"}").getBytes(StandardCharsets.UTF_8);
                w.writeMessage(channel, 1_000_000L * i, 1_000_000L * i, p, 0, p.length);
            }
        }
        return file;
    }

    @Test
    void aGoodFileIsInspected() throws IOException {
        CliRun run = CliRun.of("inspect", recording().toString());
        assertEquals(0, run.status(), run.err());
    }

    @Test
    void devZeroIsOneLine() {
        assumeTrue(Files.exists(Path.of("/dev/zero")), "no /dev/zero");
        CliRun.of("inspect", "/dev/zero").assertOneLineUserError("not a regular file");
    }

    @Test
    void aFifoIsOneLineAndDoesNotBlock() throws Exception {
        Path fifo = dir.resolve("pipe.mcap");
        Process p = new ProcessBuilder("mkfifo", fifo.toString()).start();
        assumeTrue(p.waitFor(30, TimeUnit.SECONDS) && p.exitValue() == 0, "mkfifo failed");
        CliRun.of("inspect", fifo.toString()).assertOneLineUserError("not a regular file");
        CliRun.of("replay", fifo.toString()).assertOneLineUserError("not a regular file");
    }

    @Test
    void aSparseFileOfZerosIsOneLine() throws IOException {
        Path zeros = dir.resolve("zeros.mcap");
        try (RandomAccessFile f = new RandomAccessFile(zeros.toFile(), "rw")) {
            f.setLength(3L << 30);
        }
        CliRun.of("inspect", zeros.toString()).assertOneLineUserError("no leading magic");
    }

    @Test
    void aBitFlipInACompressedChunkIsOneLine() throws IOException {
        Path file = recording();
        byte[] bytes = Files.readAllBytes(file);
        bytes[bytes.length / 3] ^= 0x04;
        Files.write(file, bytes);
        CliRun.of("inspect", file.toString()).assertOneLineUserError(file.toString());
    }

    @Test
    void anUnfinishedFileIsOneLineThatNamesRecover() throws IOException {
        Path file = recording();
        byte[] bytes = Files.readAllBytes(file);
        Files.write(file, Arrays.copyOf(bytes, bytes.length * 2 / 3));
        CliRun.of("inspect", file.toString()).assertOneLineUserError("--recover");
    }
}
