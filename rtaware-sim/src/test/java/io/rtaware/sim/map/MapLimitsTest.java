package io.rtaware.sim.map;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.zip.CRC32;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Map images too large for the heap are refused from their header, before any pixel is decoded; absurd resolutions at load. */
class MapLimitsTest {

    @TempDir
    Path dir;

    private Path yaml(String image, String resolution) throws IOException {
        Path y = dir.resolve("m.yaml");
        Files.writeString(y, "image: " + image + "\nresolution: " + resolution + "\norigin: [0.0, 0.0, 0.0]\n"
                + "occupied_thresh: 0.65\nfree_thresh: 0.196\nnegate: 0\n");
        return y;
    }

    /** A PNG whose header says width x height, with no pixel data after it: only the header can be read. */
    private static byte[] pngHeaderOnly(int width, int height) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        DataOutputStream out = new DataOutputStream(bytes);
        out.write(new byte[] {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'});
        ByteArrayOutputStream ihdr = new ByteArrayOutputStream();
        DataOutputStream h = new DataOutputStream(ihdr);
        h.writeBytes("IHDR");
        h.writeInt(width);
        h.writeInt(height);
        h.writeByte(8); // bit depth
        h.writeByte(0); // grayscale
        h.writeByte(0);
        h.writeByte(0);
        h.writeByte(0);
        byte[] chunk = ihdr.toByteArray();
        out.writeInt(chunk.length - 4);
        out.write(chunk);
        CRC32 crc = new CRC32();
        crc.update(chunk);
        out.writeInt((int) crc.getValue());
        return bytes.toByteArray();
    }

    @Test
    void aHugePngIsRefusedFromItsHeader() throws IOException {
        Files.write(dir.resolve("big.png"), pngHeaderOnly(20000, 20000));
        MapException e = assertThrows(MapException.class, () -> MapLoader.load(yaml("big.png", "0.05"), 8_000_000));
        assertTrue(e.getMessage().contains("20000 x 20000 pixels"), e.getMessage());
        assertTrue(e.getMessage().contains("at most 8000000 pixels"), e.getMessage());
        assertTrue(e.getMessage().contains("-Xmx"), "says how to raise it: " + e.getMessage());
    }

    @Test
    void aHugePgmIsRefusedFromItsHeader() throws IOException {
        Files.write(dir.resolve("big.pgm"), "P5\n10000 10000\n255\n".getBytes(StandardCharsets.US_ASCII));
        MapException e = assertThrows(MapException.class, () -> MapLoader.load(yaml("big.pgm", "0.05"), 8_000_000));
        assertTrue(e.getMessage().contains("10000 x 10000 pixels"), e.getMessage());
    }

    @Test
    void theDefaultLimitComesFromTheHeap() {
        long expected = Runtime.getRuntime().maxMemory() / 2 / MapLoader.PEAK_BYTES_PER_PIXEL;
        assertTrue(MapLoader.maxPixels() == expected, "maxPixels " + MapLoader.maxPixels());
    }

    @Test
    void anAbsurdResolutionIsRefusedAtLoad() throws IOException {
        Files.write(dir.resolve("m.pgm"), "P2\n1 1\n255\n0\n".getBytes(StandardCharsets.US_ASCII));
        MapException e = assertThrows(MapException.class, () -> MapLoader.load(yaml("m.pgm", "1e300")));
        assertTrue(e.getMessage().contains("field 'resolution' must be from 0.001 to 100 metres per pixel, got 1.0E300"),
                e.getMessage());
        assertThrows(MapException.class, () -> MapLoader.load(yaml("m.pgm", "1e-300")));
    }
}
