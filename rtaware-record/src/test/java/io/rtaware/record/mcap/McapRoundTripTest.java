package io.rtaware.record.mcap;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/** The reader reads what the writer writes, and notices corruption. */
class McapRoundTripTest {

    @TempDir
    Path dir;

    private static byte[] payload(int i) {
        return ("message " + i + " " + "x".repeat(i % 50)).getBytes(StandardCharsets.UTF_8);
    }

    private Path write(Compression compression, int messages) throws IOException {
        Path file = dir.resolve("t-" + compression + ".mcap");
        try (McapWriter w = new McapWriter(file, compression, 2048, "")) {
            int schema = w.addSchema("test/Thing", "jsonschema", "{\"type\":\"object\"}");
            int a = w.addChannel(schema, "/a", "json", Map.of("k", "v"));
            int b = w.addChannel(schema, "/b", "json", Map.of());
            w.addMetadata("rtaware.run", Map.of("command", "test"));
            for (int i = 0; i < messages; i++) {
                byte[] p = payload(i);
                w.writeMessage(i % 3 == 0 ? b : a, 1_000L * i, 1_000L * i + 1, p, 0, p.length);
            }
        }
        return file;
    }

    @ParameterizedTest
    @EnumSource(Compression.class)
    void readsBackEveryMessageAndTheSummary(Compression compression) throws IOException {
        int messages = 1000;
        Path file = write(compression, messages);
        McapReader reader = McapReader.open(file);
        List<String> topics = new ArrayList<>();
        List<byte[]> data = new ArrayList<>();
        List<Long> times = new ArrayList<>();
        List<Map<String, String>> metadata = new ArrayList<>();
        reader.read(new McapVisitor() {
            @Override
            public void metadata(String name, Map<String, String> entries) {
                metadata.add(entries);
            }

            @Override
            public void message(McapChannel channel, long sequence, long logTimeNs, long publishTimeNs,
                                byte[] bytes, int offset, int length) {
                topics.add(channel.topic());
                data.add(Arrays.copyOfRange(bytes, offset, offset + length));
                times.add(logTimeNs);
                assertEquals(logTimeNs + 1, publishTimeNs);
            }
        });
        assertEquals(messages, data.size());
        for (int i = 0; i < messages; i++) {
            assertArrayEquals(payload(i), data.get(i));
            assertEquals(i % 3 == 0 ? "/b" : "/a", topics.get(i));
            assertEquals(1_000L * i, times.get(i));
        }
        assertEquals(List.of(Map.of("command", "test")), metadata);

        McapSummary summary = reader.summary();
        McapStatistics stats = summary.statistics();
        assertEquals(messages, stats.messageCount());
        assertEquals(1, stats.schemaCount());
        assertEquals(2, stats.channelCount());
        assertEquals(1, stats.metadataCount());
        assertTrue(stats.chunkCount() > 10, "small chunks: " + stats.chunkCount());
        assertEquals(stats.chunkCount(), summary.chunkIndexCount());
        assertEquals(0, stats.messageStartNs());
        assertEquals(1_000L * (messages - 1), stats.messageEndNs());
        assertEquals(Map.of(1, 666L, 2, 334L), stats.channelMessageCounts());
        assertEquals("/a", summary.channels().get(0).topic());
        assertEquals(Map.of("k", "v"), summary.channels().get(0).metadata());
        assertEquals("test/Thing", summary.schemas().get(0).name());
    }

    @ParameterizedTest
    @EnumSource(Compression.class)
    void aFlippedByteFailsACrc(Compression compression) throws IOException {
        Path file = write(compression, 200);
        byte[] bytes = Files.readAllBytes(file);
        bytes[bytes.length / 3] ^= 0x01;
        Files.write(file, bytes);
        McapFormatException e = assertThrows(McapFormatException.class,
                () -> McapReader.open(file).read((ch, s, l, p, d, o, n) -> { }));
        assertTrue(e.getMessage().contains("CRC") || e.getMessage().contains("overruns")
                || e.getMessage().contains("zstd"), e.getMessage());
    }

    @ParameterizedTest
    @EnumSource(Compression.class)
    void aTruncatedFileIsRefused(Compression compression) throws IOException {
        Path file = write(compression, 200);
        byte[] bytes = Files.readAllBytes(file);
        Files.write(file, Arrays.copyOf(bytes, bytes.length - 20));
        assertThrows(McapFormatException.class, () -> McapReader.open(file));
    }

    /**
     * A recording commits several messages at one log time (an odometry sample, its value and its
     * transform): a chunk that fills up among them is written only after the last of them, so that
     * no two chunks share an instant ({@code mcap info}: "overlaps: no").
     */
    @ParameterizedTest
    @EnumSource(Compression.class)
    void messagesOfOneLogTimeStayInOneChunkSoChunksDoNotShareAnInstant(Compression compression) throws IOException {
        Path file = dir.resolve("same-time-" + compression + ".mcap");
        int instants = 400;
        int perInstant = 7;
        try (McapWriter w = new McapWriter(file, compression, 2048, "")) {
            int schema = w.addSchema("test/Thing", "jsonschema", "{\"type\":\"object\"}");
            int a = w.addChannel(schema, "/a", "json", Map.of());
            for (int t = 0; t < instants; t++) {
                for (int k = 0; k < perInstant; k++) {
                    byte[] p = payload(t + k);
                    w.writeMessage(a, 1_000L * t, 1_000L * t, p, 0, p.length);
                }
            }
        }
        List<long[]> chunks = new ArrayList<>();
        long[] messages = {0};
        McapReader.open(file).read(new McapVisitor() {
            @Override
            public void chunk(long fileOffset, long startNs, long endNs) {
                chunks.add(new long[] {startNs, endNs});
            }

            @Override
            public void message(McapChannel channel, long sequence, long logTimeNs, long publishTimeNs,
                                byte[] bytes, int offset, int length) {
                messages[0]++;
            }
        });
        assertEquals((long) instants * perInstant, messages[0]);
        assertTrue(chunks.size() > 10, "small chunks: " + chunks.size());
        for (int i = 1; i < chunks.size(); i++) {
            assertTrue(chunks.get(i - 1)[1] < chunks.get(i)[0], "chunk " + (i - 1) + " ends at "
                    + chunks.get(i - 1)[1] + " ns, chunk " + i + " starts at " + chunks.get(i)[0] + " ns");
        }
    }

    /** One instant holding more than {@value McapWriter#SHARED_TIME_CHUNK_FACTOR} chunk sizes is split all the same. */
    @ParameterizedTest
    @EnumSource(Compression.class)
    void anInstantOfManyChunkSizesIsSplitAllTheSame(Compression compression) throws IOException {
        Path file = dir.resolve("one-instant-" + compression + ".mcap");
        int messages = 2000;
        try (McapWriter w = new McapWriter(file, compression, 2048, "")) {
            int schema = w.addSchema("test/Thing", "jsonschema", "{\"type\":\"object\"}");
            int a = w.addChannel(schema, "/a", "json", Map.of());
            for (int i = 0; i < messages; i++) {
                byte[] p = payload(i);
                w.writeMessage(a, 5_000L, 5_000L, p, 0, p.length);
            }
        }
        McapReader reader = McapReader.open(file);
        reader.read((ch, s, l, p, d, o, n) -> { });
        McapStatistics stats = reader.summary().statistics();
        assertEquals(messages, stats.messageCount());
        assertTrue(stats.chunkCount() > 1, "chunks: " + stats.chunkCount());
    }
}
