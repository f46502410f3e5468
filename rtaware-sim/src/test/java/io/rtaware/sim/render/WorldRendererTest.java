package io.rtaware.sim.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

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
        r.writePng(img, png);
        BufferedImage back = ImageIO.read(png.toFile());
        assertEquals(500, back.getWidth());
    }

    @Test
    void drawsWithoutMap() {
        Scenario s = new Scenario("x", Optional.empty(), new Pose2d(0, 0, 0), List.of(new Point2d(2, 1)), 0.3, 10);
        BufferedImage img = new WorldRenderer().render(s);
        assertEquals(320, img.getWidth());
        assertEquals(240, img.getHeight());
    }
}
