package io.rtaware.record.mcap;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.testing.PythonPeers;
import io.rtaware.core.testing.Requires;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Files written by another implementation (the official Python {@code mcap} writer) with what
 * rtaware's writer never produces: lz4 chunks, and no summary section. Both are valid MCAP and
 * must read exactly.
 */
class ForeignMcapFilesTest {

    @TempDir
    Path dir;

    @ParameterizedTest
    @ValueSource(booleans = {true, false})
    @Requires(PythonPeers.class)
    void lz4ChunksWithAndWithoutASummaryReadExactly(boolean withSummary) throws Exception {
        int count = 500;
        Path file = dir.resolve("foreign.mcap");
        if (withSummary) {
            PeerPython.run("write_foreign_mcap.py", file.toString(), Integer.toString(count));
        } else {
            PeerPython.run("write_foreign_mcap.py", file.toString(), Integer.toString(count), "--no-summary");
        }
        McapReader reader = McapReader.open(file);
        List<String> seen = new ArrayList<>();
        long[] chunks = {0};
        reader.read(new McapVisitor() {
            @Override
            public void chunk(long fileOffset, long startNs, long endNs) {
                chunks[0]++;
            }

            @Override
            public void message(McapChannel channel, long sequence, long logTimeNs, long publishTimeNs,
                                byte[] data, int offset, int length) {
                assertEquals(1000L * seen.size(), logTimeNs, "log time of message " + seen.size());
                assertEquals(seen.size() % 2 == 1 ? "/b" : "/a", channel.topic());
                seen.add(new String(data, offset, length, StandardCharsets.UTF_8));
            }
        });
        assertEquals(count, seen.size());
        assertEquals("foreign 499", seen.get(count - 1));
        assertTrue(chunks[0] > 5, "several lz4 chunks: " + chunks[0]);
        McapSummary summary = reader.summary();
        assertEquals(count, summary.statistics().messageCount(), "statistics (read or, without a summary, counted)");
        assertEquals(0, summary.statistics().messageStartNs());
        assertEquals(1000L * (count - 1), summary.statistics().messageEndNs());
        assertEquals(List.of("/a", "/b"), summary.channels().stream().map(McapChannel::topic).toList());
    }
}
