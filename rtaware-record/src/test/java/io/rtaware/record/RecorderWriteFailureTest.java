package io.rtaware.record;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.record.mcap.Compression;
import io.rtaware.record.mcap.McapFormatException;
import io.rtaware.record.mcap.McapReader;
import io.rtaware.record.mcap.McapWriter;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.channels.WritableByteChannel;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 24, finding 3, at the recorder: a disk that fills up mid-run ends the writing with the
 * reason, and the statistics count exactly what the file holds (the messages of its whole chunks).
 */
class RecorderWriteFailureTest {

    @TempDir
    Path dir;

    /** A file that accepts {@code capacity} bytes and then fails as a full disk does. */
    private static final class SmallDisk implements WritableByteChannel {
        private final FileChannel file;
        private long left;

        SmallDisk(Path path, long capacity) throws IOException {
            file = FileChannel.open(path, StandardOpenOption.CREATE, StandardOpenOption.WRITE);
            left = capacity;
        }

        @Override
        public int write(ByteBuffer src) throws IOException {
            if (left == 0) {
                throw new IOException("No space left on device");
            }
            int n = (int) Math.min(left, src.remaining());
            ByteBuffer part = src.slice().limit(n);
            int written = file.write(part);
            src.position(src.position() + written);
            left -= written;
            return written;
        }

        @Override
        public boolean isOpen() {
            return file.isOpen();
        }

        @Override
        public void close() throws IOException {
            file.close();
        }
    }

    @Test
    void aFullDiskEndsTheWritingWithTheReasonAndCountsWhatTheFileHolds() throws IOException {
        Path file = dir.resolve("full.mcap");
        McapWriter writer = new McapWriter(new SmallDisk(file, 20_000), Compression.NONE, 4096, "");
        RunRecorder recorder = new RunRecorder(writer, file, List.of("t"), List.of(List.of()), List.of(),
                new RecordingPlan().slots(8, 100_000, 8));
        int offered = 5_000;
        for (int i = 0; i < offered; i++) {
            recorder.cycle(0, RunRecorder.OK, 1_000_000L * i, 1_000_000L * i, 1_000_000L * i + 1000, 0, null);
        }
        RecordingStats stats = recorder.finish();
        assertNotNull(stats.error(), "the failure is reported");
        assertTrue(stats.error().contains("No space left on device"), stats.error());
        assertTrue(stats.messages() > 0 && stats.messages() < offered, "part of it is held: " + stats);
        assertEquals(20_000, stats.bytes(), "bytes written before the disk was full");

        long[] readable = {0};
        try {
            McapReader.openUnfinished(file).read((ch, s, l, p, d, o, n) -> readable[0]++);
        } catch (McapFormatException expected) {
            // the file ends inside a record: everything before it was read
        }
        assertEquals(stats.messages(), readable[0], "the statistics count exactly the messages a reader finds");
    }
}
