package io.rtaware.sim.fuzz;

import com.code_intelligence.jazzer.junit.FuzzTest;
import io.rtaware.sim.map.MapException;
import io.rtaware.sim.map.MapLoader;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Coverage-guided fuzzing of the {@code map_server} map loader (issue 24): the input is the map's
 * YAML, a zero byte, then the image it names (PGM P5 or P2, or PNG). A malformed map may only be
 * refused with a {@link MapException}; any other throwable, and an allocation beyond the pixel
 * budget given to the loader, is a finding. Without {@code JAZZER_FUZZ=1} it replays the corpus in
 * {@code MapFuzzTestInputs/}, seeded with small binary, ASCII and negated maps.
 */
class MapFuzzTest {

    /** Pixels the fuzzed loader may allocate: small, so the fuzzer looks for bugs, not big maps. */
    private static final long MAX_PIXELS = 1 << 16;

    private static final String SMALL_MAP_YAML =
            "image: map.pgm\nresolution: 0.1\norigin: [0.0, 0.0, 0.0]\noccupied_thresh: 0.65\nfree_thresh: 0.196\n"
                    + "negate: 0\n";

    /** Writes {@code map.yaml} and {@code map.pgm} (8 x 6 cells, walls around free space) into a folder. */
    static void writeSmallMap(Path dir) throws IOException {
        int w = 8;
        int h = 6;
        byte[] head = ("P5\n" + w + " " + h + "\n255\n").getBytes(StandardCharsets.US_ASCII);
        byte[] pgm = new byte[head.length + w * h];
        System.arraycopy(head, 0, pgm, 0, head.length);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                boolean wall = x == 0 || y == 0 || x == w - 1 || y == h - 1;
                pgm[head.length + y * w + x] = (byte) (wall ? 0 : 254);
            }
        }
        Files.write(dir.resolve("map.pgm"), pgm);
        Files.writeString(dir.resolve("map.yaml"), SMALL_MAP_YAML);
    }

    @FuzzTest(maxDuration = "20s")
    void loadingAMapThrowsNothingButMapErrors(byte[] input) {
        int split = 0;
        while (split < input.length && input[split] != 0) {
            split++;
        }
        ByteArrayInputStream yaml = new ByteArrayInputStream(input, 0, split);
        int imageStart = Math.min(split + 1, input.length);
        try {
            MapLoader.load("fuzz.yaml", yaml, name -> new ByteArrayInputStream(input, imageStart,
                    input.length - imageStart), MAX_PIXELS);
        } catch (MapException refused) {
            // the user's one line
        }
    }
}
