package io.rtaware.live;

import io.rtaware.robot.msg.OccupancyGrid;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import javax.imageio.ImageIO;

/**
 * PNG images of the world and of the occupancy grid being built, one pixel per cell, top row
 * first (north up), for the page to draw under the robot. Stateless and thread-safe.
 */
final class MapImages {

    private static final int WALL = 0xff2b2b2b;
    private static final int FLOOR = 0xffffffff;
    private static final int TRANSPARENT = 0x00000000;
    private static final int SEEN_FREE = 0x4d3c8cff;
    private static final int SEEN_OCCUPIED = 0xd9e67300;

    private MapImages() {
    }

    /**
     * @param world the world's map: occupied cells are walls and obstacles
     * @return walls and obstacles dark on a white floor
     */
    static byte[] world(OccupancyGrid world) {
        int w = world.width();
        int h = world.height();
        BufferedImage image = new BufferedImage(w, h, BufferedImage.TYPE_INT_ARGB);
        for (int row = 0; row < h; row++) {
            for (int col = 0; col < w; col++) {
                image.setRGB(col, h - 1 - row, world.cell(col, row) >= OccupancyGrid.OCCUPIED ? WALL : FLOOR);
            }
        }
        return png(image);
    }

    /**
     * @param grid the occupancy grid, not empty
     * @return unknown cells transparent, free cells light blue, occupied cells orange
     */
    static byte[] grid(OccupancyGrid grid) {
        int w = grid.width();
        int h = grid.height();
        BufferedImage image = new BufferedImage(w, h, BufferedImage.TYPE_INT_ARGB);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                byte c = grid.cells[y * w + x];
                int argb = c == OccupancyGrid.UNKNOWN ? TRANSPARENT : c >= OccupancyGrid.OCCUPIED ? SEEN_OCCUPIED : SEEN_FREE;
                image.setRGB(x, h - 1 - y, argb);
            }
        }
        return png(image);
    }

    private static byte[] png(BufferedImage image) {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try {
            ImageIO.write(image, "png", bytes);
        } catch (IOException e) {
            throw new UncheckedIOException("PNG encoding into memory failed", e);
        }
        return bytes.toByteArray();
    }
}
