package io.rtaware.nav.map;

import io.rtaware.core.output.OutputFiles;
import io.rtaware.robot.msg.OccupancyGrid;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Writes an occupancy grid as a ROS {@code map_server} map: a binary PGM image (P5, 8 bits;
 * occupied 0, free 254, unknown 205; the top image row is the grid's highest y) and a YAML
 * file naming it, with the resolution, the origin of the lower-left pixel and the thresholds
 * {@code occupied_thresh: 0.65} and {@code free_thresh: 0.196}, as {@code map_saver} writes.
 * Stateless and thread-safe.
 */
public final class PgmMapWriter {

    /** PGM value of an occupied cell. */
    public static final int OCCUPIED_PIXEL = 0;
    /** PGM value of a free cell. */
    public static final int FREE_PIXEL = 254;
    /** PGM value of an unknown cell. */
    public static final int UNKNOWN_PIXEL = 205;

    private PgmMapWriter() {
    }

    /**
     * Writes {@code <baseName>.pgm} and {@code <baseName>.yaml} into a directory, creating it
     * if needed, each whole or not at all ({@link OutputFiles#write}: a write that fails, e.g. on
     * a full disk, leaves no partial file and an older map as it was).
     *
     * @param map the grid; must not be empty
     * @param directory the folder
     * @param baseName file name without extension, e.g. {@code map}
     * @return the YAML file's path
     * @throws IOException if writing fails
     * @throws IllegalArgumentException if the grid is empty
     */
    public static Path write(OccupancyGrid map, Path directory, String baseName) throws IOException {
        OutputFiles.Content image = pgm(map);
        Path pgm = directory.resolve(baseName + ".pgm");
        Path yaml = directory.resolve(baseName + ".yaml");
        OutputFiles.write(pgm, image);
        OutputFiles.write(yaml, OutputFiles.text(yaml(map, pgm.getFileName().toString())));
        return yaml;
    }

    /**
     * @param map the grid; must not be empty
     * @return the grid as a binary PGM, the top image row the grid's highest y
     * @throws IllegalArgumentException if the grid is empty
     */
    public static OutputFiles.Content pgm(OccupancyGrid map) {
        if (map.isEmpty()) {
            throw new IllegalArgumentException("map is empty: nothing was published");
        }
        return out -> {
            int w = map.width();
            int h = map.height();
            out.write(("P5\n# rtaware occupancy grid, " + map.resolutionM + " m/pixel\n" + w + " " + h + "\n255\n")
                    .getBytes(StandardCharsets.US_ASCII));
            byte[] row = new byte[w];
            for (int y = h - 1; y >= 0; y--) {
                for (int x = 0; x < w; x++) {
                    byte c = map.cells[y * w + x];
                    row[x] = (byte) (c == OccupancyGrid.OCCUPIED ? OCCUPIED_PIXEL
                            : c == OccupancyGrid.FREE ? FREE_PIXEL : UNKNOWN_PIXEL);
                }
                out.write(row);
            }
        };
    }

    /**
     * @param map the grid
     * @param imageName the PGM's file name, as the YAML names it (beside the YAML)
     * @return the map_server YAML of the grid
     */
    public static String yaml(OccupancyGrid map, String imageName) {
        return String.format(Locale.ROOT,
                "image: %s%nresolution: %s%norigin: [%s, %s, 0.0]%nnegate: 0%noccupied_thresh: 0.65%nfree_thresh: 0.196%n",
                imageName, map.resolutionM, map.originXM, map.originYM);
    }
}
