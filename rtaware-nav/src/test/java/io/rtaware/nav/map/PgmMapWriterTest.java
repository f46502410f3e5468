package io.rtaware.nav.map;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.output.OutputFiles;
import io.rtaware.robot.msg.OccupancyGrid;
import java.io.FilterOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class PgmMapWriterTest {

    @TempDir
    Path dir;

    @Test
    void writesMapServerPgmAndYamlWithTheTopRowFirst() throws Exception {
        OccupancyGrid g = new OccupancyGrid(6);
        g.setGeometry(3, 2, 0.05, -1.5, 2.0);
        // bottom row (y = 0): occupied, free, unknown; top row (y = 1): free, free, occupied
        g.cells[0] = OccupancyGrid.OCCUPIED;
        g.cells[1] = OccupancyGrid.FREE;
        g.cells[2] = OccupancyGrid.UNKNOWN;
        g.cells[3] = OccupancyGrid.FREE;
        g.cells[4] = OccupancyGrid.FREE;
        g.cells[5] = OccupancyGrid.OCCUPIED;
        Path yaml = PgmMapWriter.write(g, dir, "map");
        byte[] pgm = Files.readAllBytes(dir.resolve("map.pgm"));
        String text = new String(pgm, StandardCharsets.US_ASCII);
        assertTrue(text.startsWith("P5\n"));
        assertTrue(text.contains("\n3 2\n255\n"));
        byte[] pixels = Arrays.copyOfRange(pgm, pgm.length - 6, pgm.length);
        assertArrayEquals(new byte[] {(byte) 254, (byte) 254, 0, 0, (byte) 254, (byte) 205}, pixels);
        String y = Files.readString(yaml);
        assertTrue(y.contains("image: map.pgm"));
        assertTrue(y.contains("resolution: 0.05"));
        assertTrue(y.contains("origin: [-1.5, 2.0, 0.0]"));
        assertTrue(y.contains("occupied_thresh: 0.65"));
        assertTrue(y.contains("free_thresh: 0.196"));
        assertEquals("map.yaml", yaml.getFileName().toString());
    }

    /** An output stream that fails like a full disk once {@code room} bytes have gone through. */
    private static final class FullDisk extends FilterOutputStream {
        private int room;

        FullDisk(OutputStream out, int room) {
            super(out);
            this.room = room;
        }

        @Override
        public void write(int b) throws IOException {
            if (room-- <= 0) {
                throw new IOException("No space left on device");
            }
            out.write(b);
        }
    }

    /**
     * Issue 38: {@code --out} on a full disk left a 0-byte map.pgm. The map's content, cut short
     * by a stream that fails like a full disk, leaves no map.pgm (and an older one as it was).
     */
    @Test
    void aMapCutShortByAFullDiskLeavesNoPartialFile() throws Exception {
        OccupancyGrid g = new OccupancyGrid(400);
        g.setGeometry(20, 20, 0.05, 0, 0);
        OutputFiles.Content pgm = PgmMapWriter.pgm(g);
        Path file = dir.resolve("map.pgm");
        IOException e = assertThrows(IOException.class, () -> OutputFiles.write(file, out -> pgm.writeTo(new FullDisk(out, 64))));
        assertEquals("No space left on device", e.getMessage());
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(List.of(), files.toList(), "no map.pgm, empty or cut short, and no temporary file");
        }
        Files.writeString(file, "the older map");
        assertThrows(IOException.class, () -> OutputFiles.write(file, out -> pgm.writeTo(new FullDisk(out, 64))));
        assertEquals("the older map", Files.readString(file));
        PgmMapWriter.write(g, dir, "map");
        assertEquals(PgmMapWriter.yaml(g, "map.pgm"), Files.readString(dir.resolve("map.yaml")));
        assertTrue(Files.size(file) > 400, "the whole map replaces the older one");
    }
}
