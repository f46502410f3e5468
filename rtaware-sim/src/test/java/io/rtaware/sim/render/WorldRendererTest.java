package io.rtaware.sim.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.output.OutputFiles;
import io.rtaware.robot.geometry.Point2d;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.sim.map.OccupancyMap;
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
        assertTrue(img.getWidth() > 500, "the 500 px map and the panel beside it: " + img.getWidth());
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
        assertEquals(img.getWidth(), back.getWidth());
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
        // the 1 m scale bar in the panel: a row with 50 px of black right of the map
        int longestBlackRun = 0;
        for (int y = 0; y < img.getHeight(); y++) {
            int run = 0;
            for (int x = 500; x < img.getWidth(); x++) {
                run = img.getRGB(x, y) == Color.BLACK.getRGB() ? run + 1 : 0;
                longestBlackRun = Math.max(longestBlackRun, run);
            }
        }
        assertTrue(longestBlackRun >= 45 && longestBlackRun <= 55, "a 1 m (50 px) scale bar: " + longestBlackRun);
        // the legend grows by the two path entries, in the panel
        Scenario blank = new Scenario("x", Optional.empty(), new Pose2d(0, 0, 0), List.of(new Point2d(1, 1)), 0.3, 10);
        BufferedImage plain = new WorldRenderer(50, 0.2).render(blank, null, List.of(), List.of(), List.of());
        BufferedImage legend = new WorldRenderer(50, 0.2).render(blank, null,
                List.of(new Pose2d(0, 0, 0), new Pose2d(0.5, 0, 0)), List.of(new Pose2d(0, 0.1, 0), new Pose2d(0.5, 0.1, 0)),
                List.of());
        assertTrue(inkRightOf(legend, 100) > inkRightOf(plain, 100) + 50,
                "the legend grows by the two path entries: " + inkRightOf(legend, 100) + " vs " + inkRightOf(plain, 100));
    }

    /**
     * The picture: the legend covered waypoint 2 of the paper room. Every waypoint's
     * tolerance circle and every marker, wherever on the map, shows its own colour: nothing is drawn
     * over the map.
     */
    @Test
    void theLegendAndTheCaptionNeverCoverWhatIsDrawnOnTheMap() {
        Scenario s = ScenarioLoader.load("paper-room");
        double ppm = 80;
        OccupancyMap map = s.map().orElseThrow();
        // a marker in each corner of the room and one by each waypoint
        List<Point2d> markers = new java.util.ArrayList<>(List.of(new Point2d(map.originXM() + 0.4, map.originYM() + 0.4),
                new Point2d(map.originXM() + map.widthM() - 0.4, map.originYM() + 0.4),
                new Point2d(map.originXM() + 0.4, map.originYM() + map.heightM() - 0.4),
                new Point2d(map.originXM() + map.widthM() - 0.4, map.originYM() + map.heightM() - 0.4)));
        s.waypoints().forEach(w -> markers.add(new Point2d(w.xM() - 0.5, w.yM())));
        BufferedImage img = new WorldRenderer(ppm, 0.2).render(s, map, List.of(), List.of(), markers,
                "completed: finish reached by odometry; 1.06 m from it in truth");
        for (int i = 0; i < s.waypoints().size(); i++) {
            Point2d w = s.waypoints().get(i);
            double x = (w.xM() - map.originXM()) * ppm;
            double top = (map.originYM() + map.heightM() - w.yM() - s.goalToleranceM()) * ppm;
            Color expected = i == s.waypoints().size() - 1 ? WorldRenderer.FINISH : WorldRenderer.WAYPOINT;
            assertTrue(nearest(img, x, top, expected) < 30, "waypoint " + (i + 1) + "'s circle is visible: "
                    + nearest(img, x, top, expected));
        }
        for (Point2d m : markers) {
            double x = (m.xM() - map.originXM()) * ppm;
            double y = (map.originYM() + map.heightM() - m.yM()) * ppm;
            assertTrue(nearest(img, x, y, WorldRenderer.MARKER) < 30, "the marker at " + m + " is visible");
        }
    }

    @Test
    void theCaptionIsWrappedIntoThePanelBesideTheMap() {
        Scenario s = ScenarioLoader.load("paper-room");
        OccupancyMap map = s.map().orElseThrow();
        int mapW = (int) Math.ceil(map.widthM() * 80);
        String caption = "completed: finish reached by odometry; 1.06 m from it in truth. " + "A long sentence ".repeat(8);
        BufferedImage with = new WorldRenderer().render(s, map, List.of(), List.of(), List.of(), caption);
        BufferedImage without = new WorldRenderer().render(s, map, List.of(), List.of(), List.of(), null);
        int differing = 0;
        for (int y = 0; y < Math.min(with.getHeight(), without.getHeight()); y++) {
            for (int x = 0; x < with.getWidth(); x++) {
                if (with.getRGB(x, y) != without.getRGB(x, y)) {
                    assertTrue(x >= mapW, "the caption changes only the panel, not the map: pixel " + x + "," + y);
                    differing++;
                }
            }
        }
        assertTrue(differing > 200, "the caption is drawn: " + differing + " pixels");
        for (int y = 0; y < with.getHeight(); y++) {
            for (int x = with.getWidth() - 3; x < with.getWidth(); x++) {
                assertEquals(Color.WHITE.getRGB(), with.getRGB(x, y), "the caption fits the image: ink at " + x + "," + y);
            }
        }
    }

    /** The smallest sum of RGB channel differences from {@code expected} among the 3 x 3 pixels around (x, y). */
    private static int nearest(BufferedImage img, double x, double y, Color expected) {
        int best = Integer.MAX_VALUE;
        for (int dx = -1; dx <= 1; dx++) {
            for (int dy = -1; dy <= 1; dy++) {
                Color c = new Color(img.getRGB((int) x + dx, (int) y + dy));
                best = Math.min(best, Math.abs(c.getRed() - expected.getRed())
                        + Math.abs(c.getGreen() - expected.getGreen()) + Math.abs(c.getBlue() - expected.getBlue()));
            }
        }
        return best;
    }

    private static int inkRightOf(BufferedImage img, int x0) {
        int ink = 0;
        for (int x = x0; x < img.getWidth(); x++) {
            for (int y = 0; y < img.getHeight(); y++) {
                ink += img.getRGB(x, y) == Color.WHITE.getRGB() ? 0 : 1;
            }
        }
        return ink;
    }

    @Test
    void drawsWithoutMap() {
        Scenario s = new Scenario("x", Optional.empty(), new Pose2d(0, 0, 0), List.of(new Point2d(2, 1)), 0.3, 10);
        BufferedImage img = new WorldRenderer().render(s);
        assertTrue(img.getWidth() > 320, "the 320 px area and the panel: " + img.getWidth());
        assertEquals(240, img.getHeight());
    }
}
