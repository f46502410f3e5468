package io.rtaware.app.record;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.app.CliRun;
import io.rtaware.record.mcap.Compression;
import io.rtaware.record.mcap.McapReader;
import io.rtaware.record.mcap.McapWriter;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Issue 28: {@code inspect --recover FILE} writes a valid file of every complete chunk and says what was lost. */
class RecoverTest {

    private static final int MESSAGES = 3000;

    @TempDir
    Path dir;

    private static String payload(int i) {
        return "{\"i\":" + i + ",\"pad\":\"" + "r".repeat(i % 17) + "\"}";
    }

    private Path unfinished(double keptFraction) throws IOException {
        Path whole = dir.resolve("whole.mcap");
        try (McapWriter w = new McapWriter(whole, Compression.ZSTD, 4096, "")) {
            int schema = w.addSchema("test/Thing", "jsonschema", "{}");
            int channel = w.addChannel(schema, "/a", "json", Map.of());
            w.addMetadata("rtaware.run", Map.of("command", "test"));
            for (int i = 0; i < MESSAGES; i++) {
                byte[] p = payload(i).getBytes(StandardCharsets.UTF_8);
                w.writeMessage(channel, 1_000_000L * i, 1_000_000L * i, p, 0, p.length);
            }
        }
        byte[] bytes = Files.readAllBytes(whole);
        Path cut = dir.resolve("killed.mcap");
        Files.write(cut, Arrays.copyOf(bytes, (int) (bytes.length * keptFraction)));
        return cut;
    }

    @Test
    void aCutRecordingIsRecoveredUpToItsLastCompleteChunkAndTheLossIsNamed() throws IOException {
        Path cut = unfinished(0.6);
        CliRun run = CliRun.of("inspect", "--recover", cut.toString());
        assertEquals(0, run.status(), run.err());
        Path recovered = dir.resolve("killed.recovered.mcap");
        assertTrue(run.out().contains("into " + recovered), run.out());
        assertTrue(run.out().matches("(?s).*lost: the last \\d+ of " + Files.size(cut) + " bytes, from byte \\d+: .*"),
                run.out());

        List<String> read = new ArrayList<>();
        McapReader reader = McapReader.open(recovered);
        reader.read((ch, s, l, p, d, o, n) -> read.add(new String(d, o, n, StandardCharsets.UTF_8)));
        assertTrue(read.size() > MESSAGES / 3 && read.size() < MESSAGES, "part of the run: " + read.size());
        for (int i = 0; i < read.size(); i++) {
            assertEquals(payload(i), read.get(i), "message " + i + ": the recovered ones are the first, without gaps");
        }
        assertEquals(read.size(), reader.summary().statistics().messageCount());
        assertTrue(run.out().contains("recovered " + read.size() + " messages"), run.out());
        assertEquals(0, CliRun.of("inspect", recovered.toString()).status(), "the recovered file inspects");

        CliRun.of("inspect", "--recover", cut.toString()).assertOneLineUserError("exists; move it away first");
    }

    /**
     * A writer killed between two records leaves a file that ends cleanly: after its data end
     * record but before its summary and footer, or before its data end. Neither is whole.
     */
    @Test
    void aFileCutBetweenRecordsIsNotCalledWhole() throws IOException {
        Path whole = unfinished(1.0);
        byte[] bytes = Files.readAllBytes(whole);
        ByteBuffer footer = ByteBuffer.wrap(bytes, bytes.length - 8 - 29, 29).order(ByteOrder.LITTLE_ENDIAN);
        assertEquals(0x02, footer.get(), "the footer's opcode");
        footer.getLong(); // its length
        long summaryStart = footer.getLong();
        long dataEnd = (summaryStart == 0 ? bytes.length - 8 - 29 : summaryStart) - 13;
        assertEquals(0x0F, bytes[(int) dataEnd], "the data end record's opcode");
        String[] problems = {
            "the file ends after a complete record, without its data end, summary and footer",
            "MCAP data section has no data-end record"};
        long[] cuts = {dataEnd + 13, dataEnd};
        for (int i = 0; i < cuts.length; i++) {
            Path cut = Files.write(dir.resolve("killed" + i + ".mcap"), Arrays.copyOf(bytes, (int) cuts[i]));
            CliRun run = CliRun.of("inspect", "--recover", cut.toString());
            assertEquals(0, run.status(), run.err());
            assertTrue(run.out().contains("recovered " + MESSAGES + " messages"), run.out());
            assertTrue(run.out().contains("lost: no message (every record of " + cut + " was read), but "), run.out());
            assertTrue(run.out().contains(problems[i]), run.out());
        }
    }

    @Test
    void aWholeFileLosesNothing() throws IOException {
        Path whole = unfinished(1.0);
        CliRun run = CliRun.of("inspect", "--recover", whole.toString());
        assertEquals(0, run.status(), run.err());
        assertTrue(run.out().contains("recovered " + MESSAGES + " messages"), run.out());
        assertTrue(run.out().contains("lost: nothing"), run.out());
    }

    @Test
    void aFileThatIsNotMcapIsOneLine() throws IOException {
        Path text = Files.writeString(dir.resolve("notes.mcap"), "not a recording");
        CliRun.of("inspect", "--recover", text.toString()).assertOneLineUserError("no leading magic");
    }
}
