package io.rtaware.sim.render;

import io.rtaware.robot.geometry.Point2d;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.sim.map.OccupancyMap;
import io.rtaware.sim.scenario.Scenario;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;

/**
 * Draws a scenario to an image (headless java.awt): free space white, obstacles black, unknown
 * grey, the start as a green disc of the robot's size with a heading line, waypoints as blue
 * tolerance circles numbered 1..n, the finish in red, and optionally a driven trajectory (a
 * dark blue polyline) and markers (orange crosses, e.g. where deadlines were missed).
 * Without a map, the picture spans the scenario's points with a margin. Immutable and
 * thread-safe (each call draws on its own image).
 */
public final class WorldRenderer {

    private static final Color FREE = Color.WHITE;
    private static final Color OBSTACLE = Color.BLACK;
    private static final Color UNKNOWN = new Color(0xB0, 0xB0, 0xB0);
    private static final Color START = new Color(0x1B, 0x9E, 0x3E);
    private static final Color WAYPOINT = new Color(0x1F, 0x5F, 0xD0);
    private static final Color FINISH = new Color(0xD0, 0x20, 0x20);
    private static final Color PATH = new Color(0x10, 0x20, 0x70);
    private static final Color MARKER = new Color(0xF0, 0x80, 0x00);

    private final double pixelsPerM;
    private final double robotRadiusM;

    /**
     * @param pixelsPerM image scale in pixels per metre, 5..1000
     * @param robotRadiusM radius drawn for the robot at the start, metres, positive
     * @throws IllegalArgumentException naming the parameter and value if out of range
     */
    public WorldRenderer(double pixelsPerM, double robotRadiusM) {
        if (!(pixelsPerM >= 5 && pixelsPerM <= 1000)) {
            throw new IllegalArgumentException("pixelsPerM must be in 5..1000, got " + pixelsPerM);
        }
        if (!(robotRadiusM > 0) || Double.isInfinite(robotRadiusM)) {
            throw new IllegalArgumentException("robotRadiusM must be positive, got " + robotRadiusM);
        }
        this.pixelsPerM = pixelsPerM;
        this.robotRadiusM = robotRadiusM;
    }

    /** A renderer at 80 pixels per metre for a 0.2 m robot. */
    public WorldRenderer() {
        this(80.0, 0.2);
    }

    /**
     * Draws the scenario alone (the picture of {@code rtaware world}).
     *
     * @param scenario the scenario; its map, if any, is drawn
     * @return the image
     */
    public BufferedImage render(Scenario scenario) {
        return render(scenario, scenario.map().orElse(null), List.of(), List.of());
    }

    /**
     * Draws the scenario, a driven trajectory and markers.
     *
     * @param scenario start and waypoints
     * @param map the map to draw, or null to draw a blank area around the points
     * @param trajectory poses driven, in order (may be empty)
     * @param markers points to mark (may be empty)
     * @return the image
     */
    public BufferedImage render(Scenario scenario, OccupancyMap map, List<Pose2d> trajectory, List<Point2d> markers) {
        double minX;
        double minY;
        double maxX;
        double maxY;
        if (map != null) {
            minX = map.originXM();
            minY = map.originYM();
            maxX = minX + map.widthM();
            maxY = minY + map.heightM();
        } else {
            minX = scenario.start().xM();
            maxX = minX;
            minY = scenario.start().yM();
            maxY = minY;
            for (Point2d p : scenario.waypoints()) {
                minX = Math.min(minX, p.xM());
                maxX = Math.max(maxX, p.xM());
                minY = Math.min(minY, p.yM());
                maxY = Math.max(maxY, p.yM());
            }
            for (Pose2d p : trajectory) {
                minX = Math.min(minX, p.xM());
                maxX = Math.max(maxX, p.xM());
                minY = Math.min(minY, p.yM());
                maxY = Math.max(maxY, p.yM());
            }
            minX -= 1;
            minY -= 1;
            maxX += 1;
            maxY += 1;
        }
        int w = Math.max(1, (int) Math.ceil((maxX - minX) * pixelsPerM));
        int h = Math.max(1, (int) Math.ceil((maxY - minY) * pixelsPerM));
        BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        try {
            g.setColor(FREE);
            g.fillRect(0, 0, w, h);
            if (map != null) {
                drawMap(img, map, minX, maxY);
            }
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            View v = new View(minX, maxY, pixelsPerM);
            drawCourse(g, v, scenario);
            drawTrajectory(g, v, trajectory);
            drawMarkers(g, v, markers);
        } finally {
            g.dispose();
        }
        return img;
    }

    /**
     * Writes an image as PNG, creating parent directories.
     *
     * @param image the image
     * @param file destination
     * @throws UncheckedIOException if writing fails
     */
    public void writePng(BufferedImage image, Path file) {
        try {
            Path parent = file.toAbsolutePath().getParent();
            if (parent != null) {
                Files.createDirectories(parent);
            }
            if (!ImageIO.write(image, "png", file.toFile())) {
                throw new IOException("no PNG writer available");
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write " + file + ": " + e.getMessage(), e);
        }
    }

    /**
     * Draws and writes in one call.
     *
     * @param scenario start and waypoints
     * @param map the map, or null
     * @param trajectory poses driven (may be empty)
     * @param markers points to mark (may be empty)
     * @param file destination PNG
     */
    public void writePng(Scenario scenario, OccupancyMap map, List<Pose2d> trajectory, List<Point2d> markers,
                         Path file) {
        writePng(render(scenario, map, trajectory, markers), file);
    }

    private record View(double minX, double maxY, double scale) {
        double px(double xM) {
            return (xM - minX) * scale;
        }

        double py(double yM) {
            return (maxY - yM) * scale;
        }
    }

    private void drawMap(BufferedImage img, OccupancyMap map, double minX, double maxY) {
        int w = img.getWidth();
        int h = img.getHeight();
        for (int py = 0; py < h; py++) {
            double y = maxY - (py + 0.5) / pixelsPerM;
            int row = map.rowOf(y);
            for (int px = 0; px < w; px++) {
                int col = map.colOf(minX + (px + 0.5) / pixelsPerM);
                Color c = switch (map.state(col, row)) {
                    case OCCUPIED -> OBSTACLE;
                    case UNKNOWN -> UNKNOWN;
                    case FREE -> FREE;
                };
                if (c != FREE) {
                    img.setRGB(px, py, c.getRGB());
                }
            }
        }
    }

    private void drawCourse(Graphics2D g, View v, Scenario s) {
        float stroke = (float) Math.max(1.5, pixelsPerM / 40);
        g.setStroke(new BasicStroke(stroke));
        double tol = s.goalToleranceM() * pixelsPerM;
        Font font = new Font(Font.SANS_SERIF, Font.BOLD, (int) Math.max(10, pixelsPerM / 5));
        g.setFont(font);
        List<Point2d> wps = s.waypoints();
        for (int i = 0; i < wps.size(); i++) {
            Point2d p = wps.get(i);
            boolean finish = i == wps.size() - 1;
            g.setColor(finish ? FINISH : WAYPOINT);
            g.draw(new Ellipse2D.Double(v.px(p.xM()) - tol, v.py(p.yM()) - tol, 2 * tol, 2 * tol));
            String label = finish ? (i + 1) + " finish" : Integer.toString(i + 1);
            g.drawString(label, (float) (v.px(p.xM()) + tol + 2), (float) (v.py(p.yM()) - tol / 2));
        }
        Pose2d st = s.start();
        double r = robotRadiusM * pixelsPerM;
        g.setColor(START);
        g.fill(new Ellipse2D.Double(v.px(st.xM()) - r, v.py(st.yM()) - r, 2 * r, 2 * r));
        g.setColor(Color.WHITE);
        g.draw(new Line2D.Double(v.px(st.xM()), v.py(st.yM()),
                v.px(st.xM() + robotRadiusM * Math.cos(st.yawRad())),
                v.py(st.yM() + robotRadiusM * Math.sin(st.yawRad()))));
        g.setColor(START);
        g.drawString("start", (float) (v.px(st.xM()) + r + 2), (float) (v.py(st.yM()) + r));
    }

    private void drawTrajectory(Graphics2D g, View v, List<Pose2d> trajectory) {
        if (trajectory.size() < 2) {
            return;
        }
        Path2D.Double path = new Path2D.Double();
        path.moveTo(v.px(trajectory.get(0).xM()), v.py(trajectory.get(0).yM()));
        for (int i = 1; i < trajectory.size(); i++) {
            path.lineTo(v.px(trajectory.get(i).xM()), v.py(trajectory.get(i).yM()));
        }
        g.setColor(PATH);
        g.setStroke(new BasicStroke((float) Math.max(1.0, pixelsPerM / 60)));
        g.draw(path);
    }

    private void drawMarkers(Graphics2D g, View v, List<Point2d> markers) {
        double s = Math.max(3, pixelsPerM / 12);
        g.setColor(MARKER);
        g.setStroke(new BasicStroke((float) Math.max(1.5, pixelsPerM / 40)));
        for (Point2d m : markers) {
            double x = v.px(m.xM());
            double y = v.py(m.yM());
            g.draw(new Line2D.Double(x - s, y - s, x + s, y + s));
            g.draw(new Line2D.Double(x - s, y + s, x + s, y - s));
        }
    }
}
