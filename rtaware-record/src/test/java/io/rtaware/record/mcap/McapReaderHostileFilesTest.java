package io.rtaware.record.mcap;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.io.RandomAccessFile;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * The findings of issue 24 (4) against the MCAP reader, each reproduced: files that made
 * {@code inspect} print a stack trace or run out of memory, and paths that blocked it. Every one
 * must end in one {@link McapFormatException} (an {@link IOException}), nothing else.
 */
class McapReaderHostileFilesTest {

    private static final VarHandle I64 = MethodHandles.byteArrayViewVarHandle(long[].class, ByteOrder.LITTLE_ENDIAN);
    private static final VarHandle I32 = MethodHandles.byteArrayViewVarHandle(int[].class, ByteOrder.LITTLE_ENDIAN);

    @TempDir
    Path dir;

    private Path write(Compression compression, int messages) throws IOException {
        Path file = dir.resolve("t-" + compression + ".mcap");
        try (McapWriter w = new McapWriter(file, compression, 2048, "")) {
            int schema = w.addSchema("test/Thing", "jsonschema", "{\"type\":\"object\"}");
            int a = w.addChannel(schema, "/a", "json", Map.of());
            for (int i = 0; i < messages; i++) {
                byte[] p = ("message " + i + " " + "y".repeat(i % 40)).getBytes(StandardCharsets.UTF_8);
                w.writeMessage(a, 1_000L * i, 1_000L * i, p, 0, p.length);
            }
        }
        return file;
    }

    /** Reads everything the reader offers; returns the number of messages. */
    private static long readAll(Path file) throws IOException {
        McapReader reader = McapReader.open(file);
        long[] n = {0};
        reader.read((ch, s, l, p, d, o, len) -> n[0]++);
        reader.summary();
        return n[0];
    }

    /** Where the first chunk record starts (after magic, header, schema, channel). */
    private static int firstChunk(byte[] bytes) {
        int at = Opcode.MAGIC.length;
        while (bytes[at] != Opcode.CHUNK) {
            at += 9 + (int) (long) I64.get(bytes, at + 1);
        }
        return at;
    }

    private static McapFormatException refused(Path file) {
        return assertThrows(McapFormatException.class, () -> readAll(file), "refused with one line: " + file);
    }

    @Test
    void aFifoIsRefusedWithoutBlocking() throws Exception {
        Path fifo = dir.resolve("pipe.mcap");
        Process mkfifo;
        try {
            mkfifo = new ProcessBuilder("mkfifo", fifo.toString()).start();
        } catch (IOException e) {
            assumeTrue(false, "no mkfifo here: " + e.getMessage());
            return;
        }
        assumeTrue(mkfifo.waitFor(30, TimeUnit.SECONDS) && mkfifo.exitValue() == 0, "mkfifo failed");
        // The hang guard only catches a regression that blocks forever; it measures nothing.
        McapFormatException e = assertTimeoutPreemptively(Duration.ofSeconds(60),
                () -> assertThrows(McapFormatException.class, () -> McapReader.open(fifo)));
        assertTrue(e.getMessage().contains("not a regular file"), e.getMessage());
    }

    @Test
    void devZeroIsRefusedBeforeAnythingIsRead() {
        Path zero = Path.of("/dev/zero");
        assumeTrue(Files.exists(zero), "no /dev/zero here");
        McapFormatException e = assertThrows(McapFormatException.class, () -> McapReader.open(zero));
        assertTrue(e.getMessage().contains("not a regular file"), e.getMessage());
    }

    @Test
    void aFolderIsRefused() {
        McapFormatException e = assertThrows(McapFormatException.class, () -> McapReader.open(dir));
        assertTrue(e.getMessage().contains("a folder"), e.getMessage());
    }

    @Test
    void aSparseFileOfThreeGigabytesOfZerosIsRefusedByItsMagicWithoutReadingIt() throws IOException {
        Path sparse = dir.resolve("zeros.mcap");
        try (RandomAccessFile f = new RandomAccessFile(sparse.toFile(), "rw")) {
            f.setLength(3L << 30);
        }
        McapFormatException e = assertThrows(McapFormatException.class, () -> McapReader.open(sparse));
        assertTrue(e.getMessage().contains("no leading magic"), e.getMessage());
    }

    @ParameterizedTest
    @EnumSource(Compression.class)
    void aChunkLengthOfMinusOneOverrunsTheFile(Compression compression) throws IOException {
        Path file = write(compression, 300);
        byte[] bytes = Files.readAllBytes(file);
        withoutDataCrc(bytes); // else the data section's CRC names the damage first
        I64.set(bytes, firstChunk(bytes) + 1, -1L);
        Files.write(file, bytes);
        McapFormatException e = refused(file);
        assertTrue(e.getMessage().contains("overruns the file"), e.getMessage());
    }

    @ParameterizedTest
    @EnumSource(Compression.class)
    void aChunkLengthOfGigabytesInASmallFileOverrunsIt(Compression compression) throws IOException {
        Path file = write(compression, 300);
        byte[] bytes = Files.readAllBytes(file);
        withoutDataCrc(bytes); // else the data section's CRC names the damage first
        I64.set(bytes, firstChunk(bytes) + 1, 1_500_000_000L);
        Files.write(file, bytes);
        McapFormatException e = refused(file);
        assertTrue(e.getMessage().contains("1500000000 bytes overruns the file"), e.getMessage());
    }

    @ParameterizedTest
    @EnumSource(Compression.class)
    void anUncompressedSizeOfTwoGigabytesIsRefusedBeforeAllocating(Compression compression) throws IOException {
        Path file = write(compression, 300);
        byte[] bytes = Files.readAllBytes(file);
        withoutDataCrc(bytes); // else the data section's CRC names the damage first
        // chunk: opcode, length, start, end, uncompressed size
        I64.set(bytes, firstChunk(bytes) + 9 + 16, 2_000_000_000L);
        Files.write(file, bytes);
        McapFormatException e = refused(file);
        assertTrue(e.getMessage().contains("declares 2000000000 bytes uncompressed"), e.getMessage());
    }

    @Test
    void aBitFlipInAZstdChunkIsNamedByTheDataSectionCrcBeforeZstdSeesIt() throws IOException {
        Path file = write(Compression.ZSTD, 300);
        byte[] bytes = Files.readAllBytes(file);
        int chunk = firstChunk(bytes);
        bytes[chunk + 9 + 28 + 4 + 4 + 8 + 20] ^= 0x10;
        Files.write(file, bytes);
        McapFormatException e = refused(file);
        assertTrue(e.getMessage().contains("data section CRC"), e.getMessage());
    }

    /** Zeroes the data-end CRC, as writers that skip it do, so only the chunk checks remain. */
    private static void withoutDataCrc(byte[] bytes) {
        long summaryStart = (long) I64.get(bytes, bytes.length - 8 - 20);
        int dataEnd = (int) summaryStart - 13;
        assertEquals(Opcode.DATA_END, bytes[dataEnd], "data-end record before the summary");
        I32.set(bytes, dataEnd + 9, 0);
    }

    @ParameterizedTest
    @EnumSource(Compression.class)
    void bitFlipsAtEveryOtherByteEndInOneFormatErrorOrAGoodRead(Compression compression) throws IOException {
        Path file = write(compression, 60);
        byte[] original = Files.readAllBytes(file);
        long expected = readAll(file);
        List<String> escaped = new ArrayList<>();
        for (boolean dataCrc : new boolean[] {true, false}) {
            for (int i = 0; i < original.length; i += 2) {
                byte[] bytes = original.clone();
                if (!dataCrc) {
                    withoutDataCrc(bytes);
                }
                bytes[i] ^= (byte) (1 << (i % 8));
                Files.write(file, bytes);
                try {
                    readAll(file);
                } catch (McapFormatException e) {
                    assertFalse(e.getMessage().contains("\n"), "one line: " + e.getMessage());
                } catch (IOException | RuntimeException | OutOfMemoryError e) {
                    escaped.add("byte " + i + " (data CRC " + dataCrc + "): " + e);
                }
            }
        }
        assertTrue(escaped.isEmpty(), escaped.size() + " flips escaped as other errors: " + escaped);
        Files.write(file, original);
        assertEquals(expected, readAll(file), "the undamaged file still reads");
    }

    @ParameterizedTest
    @EnumSource(Compression.class)
    void truncationsAreRefusedAsUnfinishedOrReadUpToTheirCut(Compression compression) throws IOException {
        Path file = write(compression, 60);
        byte[] original = Files.readAllBytes(file);
        for (int cut = 0; cut < original.length; cut += 5) {
            Files.write(file, Arrays.copyOf(original, cut));
            assertThrows(McapFormatException.class, () -> McapReader.open(file), "cut at " + cut);
            if (cut >= Opcode.MAGIC.length) {
                McapReader unfinished = McapReader.openUnfinished(file);
                try {
                    unfinished.read((ch, s, l, p, d, o, len) -> { });
                } catch (McapFormatException expected) {
                    assertFalse(expected.getMessage().contains("\n"), expected.getMessage());
                }
            }
        }
    }

    @Test
    void lz4ChunksReadBackExactly() throws IOException {
        Path file = write(Compression.LZ4, 500);
        List<byte[]> payloads = new ArrayList<>();
        McapReader.open(file).read((ch, s, l, p, d, o, len) -> payloads.add(Arrays.copyOfRange(d, o, o + len)));
        assertEquals(500, payloads.size());
        assertArrayEquals(("message 499 " + "y".repeat(499 % 40)).getBytes(StandardCharsets.UTF_8), payloads.get(499));
    }
}
