package io.rtaware.sim.map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class MapLoaderTest {

    @TempDir
    Path dir;

    /** 3 wide, 2 high: top row black, white, grey; bottom row white, white, black. */
    private static final int[] PIXELS = {0, 255, 128, 255, 255, 0};

    private Path yaml(String image, String extra) throws IOException {
        Path y = dir.resolve("m.yaml");
        Files.writeString(y, "image: " + image + "\nresolution: 0.5\norigin: [1.0, 2.0, 0.0]\n"
                + "occupied_thresh: 0.65\nfree_thresh: 0.196\n" + extra);
        return y;
    }

    private void checkCells(OccupancyMap m, boolean negate) {
        assertEquals(3, m.widthCells());
        assertEquals(2, m.heightCells());
        OccupancyMap.CellState occ = OccupancyMap.CellState.OCCUPIED;
        OccupancyMap.CellState free = OccupancyMap.CellState.FREE;
        // image row 0 is the top = row 1
        assertEquals(negate ? free : occ, m.state(0, 1));
        assertEquals(negate ? occ : free, m.state(1, 1));
        assertEquals(OccupancyMap.CellState.UNKNOWN, m.state(2, 1));
        assertEquals(negate ? occ : free, m.state(0, 0));
        assertEquals(negate ? free : occ, m.state(2, 0));
        // world coordinates: origin (1, 2), 0.5 m cells
        assertEquals(negate ? free : occ, m.state(m.colOf(1.25), m.rowOf(2.75)));
        assertEquals(m.isObstacle(2, 0), m.isObstacleAt(2.25, 2.25));
        assertTrue(m.isObstacleAt(0.9, 2.1));
    }

    @Test
    void loadsBinaryPgm() throws IOException {
        byte[] header = "P5\n# comment\n3 2\n255\n".getBytes(StandardCharsets.US_ASCII);
        byte[] data = new byte[header.length + 6];
        System.arraycopy(header, 0, data, 0, header.length);
        for (int i = 0; i < 6; i++) {
            data[header.length + i] = (byte) PIXELS[i];
        }
        Files.write(dir.resolve("m.pgm"), data);
        checkCells(MapLoader.load(yaml("m.pgm", "negate: 0\n")), false);
    }

    @Test
    void loadsAsciiPgmAndNegate() throws IOException {
        Files.writeString(dir.resolve("m.pgm"), "P2\n3 2\n# c\n255\n0 255 128\n255 255 0\n");
        checkCells(MapLoader.load(yaml("m.pgm", "negate: 0\n")), false);
        checkCells(MapLoader.load(yaml("m.pgm", "negate: 1\n")), true);
    }

    @Test
    void loadsPng() throws IOException {
        BufferedImage img = new BufferedImage(3, 2, BufferedImage.TYPE_INT_RGB);
        for (int i = 0; i < 6; i++) {
            int v = PIXELS[i];
            img.setRGB(i % 3, i / 3, (v << 16) | (v << 8) | v);
        }
        ImageIO.write(img, "png", dir.resolve("m.png").toFile());
        checkCells(MapLoader.load(yaml("m.png", "negate: 0\n")), false);
    }

    @Test
    void thresholdsDecideUnknown() throws IOException {
        Files.writeString(dir.resolve("m.pgm"), "P2\n3 2\n255\n0 255 128\n255 255 0\n");
        Path y = dir.resolve("t.yaml");
        Files.writeString(y, "image: m.pgm\nresolution: 0.5\norigin: [0, 0, 0]\n"
                + "occupied_thresh: 0.4\nfree_thresh: 0.1\nnegate: 0\n");
        assertEquals(OccupancyMap.CellState.OCCUPIED, MapLoader.load(y).state(2, 1));
    }

    @Test
    void distanceFieldIsEuclidean() {
        OccupancyMap.CellState[] s = new OccupancyMap.CellState[30 * 30];
        java.util.Arrays.fill(s, OccupancyMap.CellState.FREE);
        s[10 * 30 + 10] = OccupancyMap.CellState.OCCUPIED;
        OccupancyMap m = new OccupancyMap("t", 30, 30, 0.1, 0, 0, s);
        assertEquals(0.5, m.distanceCells(13, 14), 1e-6);
        assertEquals(0.0, m.distanceCells(10, 10), 1e-6);
        assertFalse(m.isObstacle(11, 11));
        // point (1.35, 1.45): nearest obstacle square [1.0, 1.1]^2, corner (1.1, 1.1)
        assertEquals(Math.hypot(0.25, 0.35), m.clearanceM(1.35, 1.45, 1.0), 1e-9);
        // the map border counts as an obstacle
        assertEquals(0.05, m.clearanceM(0.05, 2.0, 1.0), 1e-9);
    }

    private String error(String yamlText, String pgm) throws IOException {
        Files.writeString(dir.resolve("m.pgm"), pgm);
        Path y = dir.resolve("bad.yaml");
        Files.writeString(y, yamlText);
        MapException e = assertThrows(MapException.class, () -> MapLoader.load(y));
        assertFalse(e.getMessage().contains("\n"), e.getMessage());
        assertTrue(e.getMessage().contains("bad.yaml"), e.getMessage());
        return e.getMessage();
    }

    @Test
    void malformedMapsNameFileFieldAndValue() throws IOException {
        String ok = "P2\n1 1\n255\n0\n";
        String base = "image: m.pgm\norigin: [0, 0, 0]\noccupied_thresh: 0.65\nfree_thresh: 0.196\nnegate: 0\n";
        String m = error(base + "resolution: -0.1\n", ok);
        assertTrue(m.contains("'resolution'") && m.contains("-0.1"), m);
        m = error(base + "resolution: abc\n", ok);
        assertTrue(m.contains("'resolution'") && m.contains("abc"), m);
        m = error(base.replace("negate: 0", "negate: 7") + "resolution: 0.1\n", ok);
        assertTrue(m.contains("'negate'") && m.contains("7"), m);
        m = error(base.replace("origin: [0, 0, 0]", "origin: [0, 0]") + "resolution: 0.1\n", ok);
        assertTrue(m.contains("'origin'") && m.contains("[0,0]"), m);
        m = error(base.replace("m.pgm", "nope.pgm") + "resolution: 0.1\n", ok);
        assertTrue(m.contains("'image'") && m.contains("nope.pgm"), m);
        m = error(base + "resolution: 0.1\n", "P7\n1 1\n255\n0\n");
        assertTrue(m.contains("magic") && m.contains("P7"), m);
        m = error(base + "resolution: 0.1\n", "P2\n2 2\n255\n0 0 0\n");
        assertTrue(m.contains("truncated"), m);
        m = error("image: m.pgm\n", ok);
        assertTrue(m.contains("'resolution'") && m.contains("missing"), m);
    }
}
