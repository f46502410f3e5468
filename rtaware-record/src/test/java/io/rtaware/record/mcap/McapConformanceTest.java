package io.rtaware.record.mcap;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;

/**
 * {@link McapReader} against foxglove/mcap's own conformance suite (its test resources
 * {@code mcap-conformance/}, copied unchanged with their license): for every variant of every input,
 * the records the reader hands over (schemas, channels, messages and metadata, in file order, chunks
 * opened) are exactly the records of those kinds that the format's authors expect a streamed
 * reader to yield before the data end, field by field; the header's profile is theirs; and where
 * the file has a statistics record, the summary's statistics are its figures. Records rtaware's
 * reader does not hand over (attachments, indexes, summary offsets) are not compared; that the
 * reader reads past them is.
 */
class McapConformanceTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    private static Path root() {
        try {
            return Path.of(McapConformanceTest.class.getResource("/mcap-conformance").toURI());
        } catch (URISyntaxException e) {
            throw new IllegalStateException(e);
        }
    }

    private static List<Path> inputs() throws IOException {
        try (Stream<Path> files = Files.walk(root())) {
            return files.filter(f -> f.toString().endsWith(".mcap")).sorted().toList();
        }
    }

    @Test
    void theWholeSuiteIsHere() throws IOException {
        assertEquals(416, inputs().size(), "six inputs in all their variants, as foxglove/mcap publishes them");
    }

    @TestFactory
    Stream<DynamicTest> everyVariantReadsAsItsAuthorsExpect() throws IOException {
        return inputs().stream().map(file -> DynamicTest.dynamicTest(root().relativize(file).toString(),
                () -> check(file)));
    }

    private static void check(Path file) throws IOException {
        String name = file.getFileName().toString();
        JsonNode expected = JSON.readTree(file.resolveSibling(name.substring(0, name.length() - 5) + ".json").toFile());
        List<Map<String, Object>> want = new ArrayList<>();
        Map<String, Object> statistics = null;
        String profile = null;
        boolean dataEnded = false;
        for (JsonNode record : expected.path("records")) {
            String type = record.path("type").asText();
            Map<String, Object> fields = fields(type, record.path("fields"));
            switch (type) {
                case "Header" -> profile = (String) fields.get("profile");
                case "DataEnd" -> dataEnded = true;
                case "Statistics" -> statistics = fields;
                case "Schema", "Channel", "Message", "Metadata" -> {
                    if (!dataEnded) {
                        want.add(fields);
                    }
                }
                default -> { } // attachments, indexes, summary offsets, footer: not handed over
            }
        }

        McapReader reader = McapReader.open(file);
        List<Map<String, Object>> got = new ArrayList<>();
        reader.read(new McapVisitor() {
            @Override
            public void schema(McapSchema schema) {
                got.add(record("Schema", "id", (long) schema.id(), "name", schema.name(), "encoding", schema.encoding(),
                        "data", bytes(schema.data().getBytes(StandardCharsets.UTF_8), 0, -1)));
            }

            @Override
            public void channel(McapChannel channel) {
                got.add(record("Channel", "id", (long) channel.id(), "schema_id", (long) channel.schemaId(),
                        "topic", channel.topic(), "message_encoding", channel.messageEncoding(),
                        "metadata", new TreeMap<>(channel.metadata())));
            }

            @Override
            public void metadata(String metadataName, Map<String, String> entries) {
                got.add(record("Metadata", "name", metadataName, "metadata", new TreeMap<>(entries)));
            }

            @Override
            public void message(McapChannel channel, long sequence, long logTimeNs, long publishTimeNs, byte[] data,
                                int offset, int length) {
                got.add(record("Message", "channel_id", (long) channel.id(), "sequence", sequence, "log_time", logTimeNs,
                        "publish_time", publishTimeNs, "data", bytes(data, offset, length)));
            }
        });
        assertEquals(want, got, "the records of " + file.getFileName());
        assertEquals(profile, reader.profile(), "the header's profile");
        if (statistics != null) {
            McapStatistics s = reader.summary().statistics();
            Map<String, Object> counts = new TreeMap<>();
            s.channelMessageCounts().forEach((channel, count) -> counts.put(Integer.toString(channel), count));
            assertEquals(statistics, record("Statistics", "message_count", s.messageCount(),
                    "schema_count", (long) s.schemaCount(), "channel_count", s.channelCount(),
                    "attachment_count", statistics.get("attachment_count"), "metadata_count", s.metadataCount(),
                    "chunk_count", s.chunkCount(), "message_start_time", s.messageStartNs(),
                    "message_end_time", s.messageEndNs(), "channel_message_counts", counts),
                    "the statistics of " + file.getFileName() + " (attachments are not counted by rtaware)");
        }
        assertTrue(reader.finished());
    }

    /** The JSON's fields as Java values: numbers (written as strings) to longs, byte arrays to lists. */
    private static Map<String, Object> fields(String type, JsonNode fields) {
        Map<String, Object> out = new TreeMap<>();
        out.put("type", type);
        for (JsonNode pair : fields) {
            String key = pair.get(0).asText();
            JsonNode value = pair.get(1);
            out.put(key, value(key, value));
        }
        return out;
    }

    private static Object value(String key, JsonNode value) {
        if (value.isArray()) {
            List<Long> list = new ArrayList<>();
            value.forEach(v -> list.add(Long.parseLong(v.asText())));
            return list;
        }
        if (value.isObject()) {
            Map<String, Object> map = new TreeMap<>();
            for (Iterator<Map.Entry<String, JsonNode>> it = value.fields(); it.hasNext(); ) {
                Map.Entry<String, JsonNode> e = it.next();
                map.put(e.getKey(), key.equals("metadata") ? e.getValue().asText() : Long.parseLong(e.getValue().asText()));
            }
            return map;
        }
        String text = value.asText();
        boolean number = switch (key) {
            case "id", "schema_id", "channel_id", "sequence", "log_time", "publish_time", "message_count", "schema_count",
                 "channel_count", "attachment_count", "metadata_count", "chunk_count", "message_start_time",
                 "message_end_time" -> true;
            default -> false;
        };
        return number ? Long.parseLong(text) : text;
    }

    private static Map<String, Object> record(String type, Object... pairs) {
        Map<String, Object> out = new TreeMap<>();
        out.put("type", type);
        for (int i = 0; i < pairs.length; i += 2) {
            out.put((String) pairs[i], pairs[i + 1]);
        }
        return out;
    }

    private static List<Long> bytes(byte[] data, int offset, int length) {
        int end = length < 0 ? data.length : offset + length;
        List<Long> out = new ArrayList<>();
        for (int i = offset; i < end; i++) {
            out.add((long) (data[i] & 0xFF));
        }
        return out;
    }
}
