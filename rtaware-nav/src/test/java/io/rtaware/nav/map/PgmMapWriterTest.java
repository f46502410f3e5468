package io.rtaware.nav.map;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.robot.msg.OccupancyGrid;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
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
}
