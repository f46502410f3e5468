package io.rtaware.app.record;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import io.rtaware.app.CliRun;
import io.rtaware.record.RecordingPlan;
import io.rtaware.record.StateJsonMessage;
import io.rtaware.record.mcap.Compression;
import io.rtaware.record.mcap.McapChannel;
import io.rtaware.record.mcap.McapReader;
import io.rtaware.record.mcap.McapSchema;
import io.rtaware.record.mcap.McapVisitor;
import io.rtaware.record.mcap.McapWriter;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.TreeMap;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 28: replay and inspect read both the ros2-profile recordings and those of the previous
 * layout (JSON channels, log times in world time, no profile), and a recording cut short (as a
 * run killed with SIGKILL leaves it) replays, once recovered, up to its last complete chunk.
 */
class PreviousFormatTest {

    @TempDir
    static Path dir;
    private static Path recording;

    @BeforeAll
    static void recordAShortRun() throws Exception {
        Path scenario = Path.of(Objects.requireNonNull(PreviousFormatTest.class.getResource("/scenarios/short-leg.yaml"))
                .toURI());
        recording = dir.resolve("run.mcap");
        CliRun run = CliRun.of("run", "--scenario", scenario.toString(), "--time-scale", "10", "--out",
                dir.resolve("run").toString(), "--quiet", "--seed", "5", "--record", recording.toString());
        assertEquals(0, run.status(), run.err());
    }

    /** Per task: cycles, identical and different, as replay.json counts them. */
    private static Map<String, List<Long>> replay(Path file, String name) throws IOException {
        Path out = dir.resolve(name);
        CliRun replay = CliRun.of("replay", file.toString(), "--out", out.toString());
        assertEquals(0, replay.status(), replay.err());
        JsonNode json = new ObjectMapper().readTree(out.resolve("replay.json").toFile());
        Map<String, List<Long>> tasks = new TreeMap<>();
        for (JsonNode t : json.path("tasks")) {
            tasks.put(t.path("name").asText(), List.of(t.path("cycles").asLong(), t.path("identical").asLong(),
                    t.path("different").asLong()));
        }
        assertTrue(tasks.size() >= 5, name + ": the controller's tasks replayed: " + tasks);
        return tasks;
    }

    @Test
    void aRecordingInThePreviousLayoutStillInspectsAndReplaysAsTheNewOne() throws IOException {
        Path previous = dir.resolve("previous.mcap");
        writeInThePreviousLayout(recording, previous);
        CliRun inspect = CliRun.of("inspect", previous.toString());
        assertEquals(0, inspect.status(), inspect.err());
        assertTrue(inspect.out().contains("(jsonschema)"), "the previous layout's JSON channels: " + inspect.out());
        assertEquals(replay(recording, "replay-now"), replay(previous, "replay-previous"),
                "every task replays the same cycles with the same outcome from both layouts");
    }

    @Test
    void aRecordingCutShortReplaysUpToItsLastCompleteChunkOnceRecovered() throws IOException {
        byte[] whole = Files.readAllBytes(recording);
        Path killed = Files.write(dir.resolve("killed.mcap"), Arrays.copyOf(whole, whole.length * 3 / 4));
        CliRun.of("replay", killed.toString()).assertOneLineUserError("--recover");
        CliRun recover = CliRun.of("inspect", "--recover", killed.toString());
        assertEquals(0, recover.status(), recover.err());
        Map<String, List<Long>> part = replay(dir.resolve("killed.recovered.mcap"), "replay-recovered");
        Map<String, List<Long>> all = replay(recording, "replay-whole");
        assertEquals(all.keySet(), part.keySet());
        for (String task : all.keySet()) {
            long cycles = part.get(task).get(0);
            assertTrue(cycles > 0 && cycles < all.get(task).get(0), task + ": part of the run's cycles: " + cycles);
            assertTrue(part.get(task).get(2) <= all.get(task).get(2), task + ": no difference the whole file lacks");
        }
    }

    /**
     * Rewrites a recording as rtaware wrote them before the ros2 profile: StateJson channels as
     * JSON with a jsonschema, log times and header stamps in world time, no log-time offset, no
     * rosbag2 record, no profile.
     */
    private static void writeInThePreviousLayout(Path from, Path to) throws IOException {
        Map<Integer, McapSchema> schemas = new HashMap<>();
        Map<Integer, Integer> channels = new HashMap<>();
        Map<Integer, Boolean> json = new HashMap<>();
        long[] offset = {0};
        try (McapWriter w = new McapWriter(to, Compression.ZSTD, McapWriter.DEFAULT_CHUNK_BYTES, "")) {
            McapReader.open(from).read(new McapVisitor() {
                @Override
                public void schema(McapSchema schema) {
                    schemas.put(schema.id(), schema);
                }

                @Override
                public void metadata(String name, Map<String, String> entries) {
                    if (!name.equals("rtaware.run")) {
                        return;
                    }
                    offset[0] = Long.parseLong(entries.get(RecordingPlan.LOG_TIME_OFFSET_NS));
                    Map<String, String> kept = new LinkedHashMap<>(entries);
                    kept.remove(RecordingPlan.LOG_TIME_OFFSET_NS);
                    unchecked(() -> w.addMetadata(name, kept));
                }

                @Override
                public void channel(McapChannel channel) {
                    Map<String, String> m = new LinkedHashMap<>(channel.metadata());
                    boolean isJson = StateJsonMessage.JSON.equals(m.remove(StateJsonMessage.VALUE_ENCODING));
                    String jsonSchema = m.remove("json_schema");
                    m.remove("value_type");
                    m.remove("offered_qos_profiles");
                    m.remove("topic_type_hash");
                    McapSchema s = schemas.get(channel.schemaId());
                    unchecked(() -> {
                        int schema = isJson ? w.addSchema("rtaware/state/" + channel.metadata().get("key"), "jsonschema",
                                jsonSchema) : w.addSchema(s.name(), s.encoding(), s.data());
                        channels.put(channel.id(), w.addChannel(schema, channel.topic(), isJson ? "json" : "cdr", m));
                    });
                    json.put(channel.id(), isJson);
                    json.put(-channel.id(), s.data().startsWith("std_msgs/Header header"));
                }

                @Override
                public void message(McapChannel channel, long sequence, long logTimeNs, long publishTimeNs,
                                    byte[] data, int off, int length) {
                    byte[] bytes = json.get(channel.id()) ? StateJsonMessage.json(data, off, length)
                            : Arrays.copyOfRange(data, off, off + length);
                    if (json.get(-channel.id())) {
                        restamp(bytes, logTimeNs, logTimeNs - offset[0]);
                    }
                    unchecked(() -> w.writeMessage(channels.get(channel.id()), sequence, logTimeNs - offset[0],
                            publishTimeNs - offset[0], bytes, 0, bytes.length));
                }
            });
        }
    }

    /** Replaces every header stamp (int32 sec, uint32 nsec at 4-aligned places) of {@code fromNs} by {@code toNs}. */
    private static void restamp(byte[] cdr, long fromNs, long toNs) {
        ByteBuffer b = ByteBuffer.wrap(cdr).order(ByteOrder.LITTLE_ENDIAN);
        int fromSec = (int) Math.floorDiv(fromNs, 1_000_000_000L);
        int fromNsec = (int) Math.floorMod(fromNs, 1_000_000_000L);
        for (int at = 4; at + 8 <= cdr.length; at += 4) {
            if (b.getInt(at) == fromSec && b.getInt(at + 4) == fromNsec) {
                b.putInt(at, (int) Math.floorDiv(toNs, 1_000_000_000L));
                b.putInt(at + 4, (int) Math.floorMod(toNs, 1_000_000_000L));
            }
        }
    }

    private interface IoAction {
        void run() throws IOException;
    }

    private static void unchecked(IoAction action) {
        try {
            action.run();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
