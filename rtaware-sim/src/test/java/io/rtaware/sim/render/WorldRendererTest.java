package io.rtaware.sim.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.output.OutputFiles;
import io.rtaware.robot.geometry.Point2d;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.sim.scenario.Scenario;
import io.rtaware.sim.scenario.ScenarioLoader;
import java.awt.Color;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class WorldRendererTest {

    @TempDir
    Path dir;

    @Test
    void drawsPaperRoomToPng() throws Exception {
        Scenario s = ScenarioLoader.load("paper-room");
        WorldRenderer r = new WorldRenderer(50, 0.2);
        BufferedImage img = r.render(s, s.map().orElseThrow(),
                List.of(new Pose2d(0.8, 0.8, 0), new Pose2d(3.0, 1.5, 0)), List.of(new Point2d(2, 1.2)));
        assertEquals(500, img.getWidth());
        assertEquals(330, img.getHeight());
        // box centre (4.8, 3.1) -> pixel ((4.8+0.2)*50, (6.4-3.1)*50) is black
        assertEquals(Color.BLACK.getRGB(), img.getRGB(250, 165));
        // free floor near (2, 5) is white
        assertEquals(Color.WHITE.getRGB(), img.getRGB(110, 70));
        // start disc centre is green-ish
        Color start = new Color(img.getRGB(50, 286));
        assertTrue(start.getGreen() > start.getRed() && start.getGreen() > start.getBlue(), start.toString());
        Path png = dir.resolve("sub/world.png");
        OutputFiles.write(png, OutputFiles.png(img));
        BufferedImage back = ImageIO.read(png.toFile());
        assertEquals(500, back.getWidth());
    }

    @Test
    void drawsTheBelievedPathDashedBesideTheTrueOneWithALegendAndAScaleBar() {
        Scenario s = ScenarioLoader.load("paper-room");
        WorldRenderer r = new WorldRenderer(50, 0.2);
        List<Pose2d> truth = List.of(new Pose2d(1.0, 1.5, 0), new Pose2d(3.0, 1.5, 0));
        List<Pose2d> believed = List.of(new Pose2d(1.0, 2.0, 0), new Pose2d(3.0, 2.0, 0));
        BufferedImage img = r.render(s, s.map().orElseThrow(), truth, believed, List.of());
        int believedRow = (int) Math.round((6.4 - 2.0) * 50);
        int purple = 0;
        int gaps = 0;
        for (int x = (int) ((1.2 + 0.2) * 50); x < (int) ((2.8 + 0.2) * 50); x++) {
            Color c = new Color(img.getRGB(x, believedRow));
            if (c.getRed() > 150 && c.getBlue() > 150 && c.getGreen() < 100) {
                purple++;
            } else if (c.equals(Color.WHITE)) {
                gaps++;
            }
        }
        assertTrue(purple > 20, "the believed path is drawn in purple: " + purple + " pixels");
        assertTrue(gaps > 5, "dashed: " + gaps + " white pixels between dashes");
        Color truthPixel = new Color(img.getRGB((int) ((2.0 + 0.2) * 50), (int) Math.round((6.4 - 1.5) * 50)));
        assertTrue(truthPixel.getBlue() > truthPixel.getRed(), "the true path is dark blue: " + truthPixel);
        // the 1 m scale bar: 50 px of black at the bottom left
        int bar = 0;
        for (int x = 10; x <= 60; x++) {
            bar += img.getRGB(x, img.getHeight() - 12) == Color.BLACK.getRGB() ? 1 : 0;
        }
        assertTrue(bar >= 45, "a 1 m (50 px) scale bar: " + bar + " black pixels");
        // the legend, top right, on a picture with nothing else there (no map, points bottom left)
        Scenario blank = new Scenario("x", Optional.empty(), new Pose2d(0, 0, 0), List.of(new Point2d(1, 1)), 0.3, 10);
        BufferedImage plain = new WorldRenderer(50, 0.2).render(blank, null, List.of(), List.of(), List.of());
        BufferedImage legend = new WorldRenderer(50, 0.2).render(blank, null,
                List.of(new Pose2d(0, 0, 0), new Pose2d(0.5, 0, 0)), List.of(new Pose2d(0, 0.1, 0), new Pose2d(0.5, 0.1, 0)),
                List.of());
        assertTrue(inkTopRight(legend) > inkTopRight(plain) + 50,
                "the legend grows by the two path entries: " + inkTopRight(legend) + " vs " + inkTopRight(plain));
    }

    private static int inkTopRight(BufferedImage img) {
        int ink = 0;
        for (int x = img.getWidth() / 2; x < img.getWidth(); x++) {
            for (int y = 0; y < img.getHeight() / 2; y++) {
                ink += img.getRGB(x, y) == Color.WHITE.getRGB() ? 0 : 1;
            }
        }
        return ink;
    }

    @Test
    void drawsWithoutMap() {
        Scenario s = new Scenario("x", Optional.empty(), new Pose2d(0, 0, 0), List.of(new Point2d(2, 1)), 0.3, 10);
        BufferedImage img = new WorldRenderer().render(s);
        assertEquals(320, img.getWidth());
        assertEquals(240, img.getHeight());
    }
}
