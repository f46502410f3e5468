package io.rtaware.sim.render;

import io.rtaware.robot.geometry.Point2d;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.sim.actor.ActorShape;
import io.rtaware.sim.actor.ActorSpec;
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
import java.util.ArrayList;
import java.util.List;

/**
 * Draws a scenario to an image (headless java.awt): free space white, obstacles black, unknown
 * grey, the start as a green disc of the robot's size with a heading line, waypoints as blue
 * tolerance circles numbered 1..n, the finish in red, and optionally a driven trajectory (a
 * dark blue polyline), the path the robot believed it drove (its odometry, a dashed purple
 * polyline) and markers (orange crosses, e.g. where deadlines were missed). Beside the map, in a
 * panel of its own on the right so that it never covers what is drawn, an optional caption (e.g.
 * how a run ended, wrapped to the panel), a legend of what is drawn and a 1 m scale bar. The
 * map keeps its pixels: a point (x, y) of the world is at the same pixel with and without the
 * panel. The scenario's actors are drawn where
 * they start, bodies filled in orange with their paths dashed, doors and obstacles outlined with
 * the time they close or appear.
 * Without a map, the picture spans the scenario's points with a margin. Write an image with
 * {@code OutputFiles.write(file, OutputFiles.png(image))}, which never deletes what stands at the
 * path. Immutable and thread-safe (each call draws on its own image).
 */
public final class WorldRenderer {

    private static final Color FREE = Color.WHITE;
    private static final Color OBSTACLE = Color.BLACK;
    private static final Color UNKNOWN = new Color(0xB0, 0xB0, 0xB0);
    private static final Color START = new Color(0x1B, 0x9E, 0x3E);
    /** The waypoints' tolerance circles. */
    static final Color WAYPOINT = new Color(0x1F, 0x5F, 0xD0);
    /** The finish's tolerance circle. */
    static final Color FINISH = new Color(0xD0, 0x20, 0x20);
    private static final Color PATH = new Color(0x10, 0x20, 0x70);
    /** The markers' crosses. */
    static final Color MARKER = new Color(0xF0, 0x80, 0x00);
    private static final Color BELIEVED = new Color(0xC0, 0x30, 0xB0);
    private static final Color ACTOR = new Color(0xE0, 0x60, 0x10);
    private static final Color ACTOR_PATH = new Color(0x90, 0x60, 0x30);
    private static final int LEGEND_FONT_PX = 13;
    /** Space between the map and the panel, and around the panel's contents, pixels. */
    private static final int PANEL_MARGIN_PX = 10;
    /** The narrowest panel: the caption wraps to this width less the margins. */
    private static final int PANEL_MIN_WIDTH_PX = 300;
    /** Height the scale bar and its label take, pixels. */
    private static final int SCALE_BAR_HEIGHT_PX = LEGEND_FONT_PX + 18;

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
        return render(scenario, map, trajectory, List.of(), markers);
    }

    /**
     * Draws the scenario, the true path, the path the robot believed it drove (its odometry,
     * dashed) and markers, with a legend of what is drawn and a 1 m scale bar.
     *
     * @param scenario start and waypoints
     * @param map the map to draw, or null to draw a blank area around the points
     * @param trajectory poses driven in truth, in order (may be empty)
     * @param believed the robot's own pose estimates at the same moments (may be empty)
     * @param markers points to mark (may be empty)
     * @return the image
     */
    public BufferedImage render(Scenario scenario, OccupancyMap map, List<Pose2d> trajectory, List<Pose2d> believed,
                                List<Point2d> markers) {
        return render(scenario, map, trajectory, believed, markers, null);
    }

    /**
     * Draws the scenario, the true path, the believed path and markers, with a caption, a legend
     * and a 1 m scale bar in a panel right of the map.
     *
     * @param scenario start and waypoints
     * @param map the map to draw, or null to draw a blank area around the points
     * @param trajectory poses driven in truth, in order (may be empty)
     * @param believed the robot's own pose estimates at the same moments (may be empty)
     * @param markers points to mark (may be empty)
     * @param caption a sentence above the legend (e.g. how the run ended), wrapped to the panel, or null
     * @return the image
     */
    public BufferedImage render(Scenario scenario, OccupancyMap map, List<Pose2d> trajectory, List<Pose2d> believed,
                                List<Point2d> markers, String caption) {
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
            for (Pose2d p : concat(trajectory, believed)) {
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
        Legend legend = legend(trajectory.size() >= 2, believed.size() >= 2, !markers.isEmpty(), scenario.actors());
        Font legendFont = new Font(Font.SANS_SERIF, Font.PLAIN, LEGEND_FONT_PX);
        int panelW = Math.max(Math.max(PANEL_MIN_WIDTH_PX, legend.width(legendFont) + 2 * PANEL_MARGIN_PX),
                (int) Math.ceil(pixelsPerM) + 3 * PANEL_MARGIN_PX); // the 1 m scale bar fits too
        Font captionFont = new Font(Font.SANS_SERIF, Font.BOLD, LEGEND_FONT_PX + 1);
        List<String> captionLines = caption == null ? List.of()
                : wrap(caption, captionFont, panelW - 2 * PANEL_MARGIN_PX);
        int captionH = captionLines.size() * (LEGEND_FONT_PX + 5) + (captionLines.isEmpty() ? 0 : PANEL_MARGIN_PX);
        int panelH = PANEL_MARGIN_PX + captionH + legend.height() + PANEL_MARGIN_PX + SCALE_BAR_HEIGHT_PX
                + PANEL_MARGIN_PX;
        int imageW = w + PANEL_MARGIN_PX + panelW;
        int imageH = Math.max(h, panelH);
        BufferedImage img = new BufferedImage(imageW, imageH, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        try {
            g.setColor(FREE);
            g.fillRect(0, 0, imageW, imageH);
            if (map != null) {
                drawMap(img, map, minX, maxY);
            }
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            View v = new View(minX, maxY, pixelsPerM);
            drawCourse(g, v, scenario);
            drawActors(g, v, scenario.actors());
            drawPath(g, v, believed, BELIEVED, true);
            drawPath(g, v, trajectory, PATH, false);
            drawMarkers(g, v, markers);
            // The panel, right of the map: its background covers labels that ran past the map's edge.
            int x0 = w + PANEL_MARGIN_PX;
            g.setColor(FREE);
            g.fillRect(x0, 0, panelW, imageH);
            g.setColor(Color.GRAY);
            g.setStroke(new BasicStroke(1f));
            g.drawLine(w, 0, w, h - 1);
            int y = PANEL_MARGIN_PX;
            g.setFont(captionFont);
            g.setColor(Color.BLACK);
            for (String line : captionLines) {
                y += LEGEND_FONT_PX + 5;
                g.drawString(line, x0 + PANEL_MARGIN_PX, y - 4);
            }
            y += captionLines.isEmpty() ? 0 : PANEL_MARGIN_PX;
            drawLegend(g, legend, legendFont, x0 + PANEL_MARGIN_PX, y);
            drawScaleBar(g, x0 + PANEL_MARGIN_PX, y + legend.height() + PANEL_MARGIN_PX + SCALE_BAR_HEIGHT_PX - 8);
        } finally {
            g.dispose();
        }
        return img;
    }

    /** Breaks a sentence at spaces into lines no wider than {@code widthPx} (a longer word stands alone). */
    private static List<String> wrap(String text, Font font, int widthPx) {
        java.awt.font.FontRenderContext frc = new java.awt.font.FontRenderContext(null, true, true);
        List<String> lines = new ArrayList<>();
        StringBuilder line = new StringBuilder();
        for (String word : text.split(" ")) {
            String candidate = line.length() == 0 ? word : line + " " + word;
            if (line.length() > 0 && font.getStringBounds(candidate, frc).getWidth() > widthPx) {
                lines.add(line.toString());
                line.setLength(0);
                line.append(word);
            } else {
                line.setLength(0);
                line.append(candidate);
            }
        }
        if (line.length() > 0) {
            lines.add(line.toString());
        }
        return lines;
    }

    private static List<Pose2d> concat(List<Pose2d> a, List<Pose2d> b) {
        List<Pose2d> all = new ArrayList<>(a);
        all.addAll(b);
        return all;
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

    private void drawPath(Graphics2D g, View v, List<Pose2d> trajectory, Color colour, boolean dashed) {
        if (trajectory.size() < 2) {
            return;
        }
        Path2D.Double path = new Path2D.Double();
        path.moveTo(v.px(trajectory.get(0).xM()), v.py(trajectory.get(0).yM()));
        for (int i = 1; i < trajectory.size(); i++) {
            path.lineTo(v.px(trajectory.get(i).xM()), v.py(trajectory.get(i).yM()));
        }
        g.setColor(colour);
        g.setStroke(stroke(dashed));
        g.draw(path);
    }

    private BasicStroke stroke(boolean dashed) {
        float width = (float) Math.max(1.0, pixelsPerM / 60);
        return dashed ? new BasicStroke(width, BasicStroke.CAP_BUTT, BasicStroke.JOIN_ROUND, 10f,
                new float[] {6 * width, 4 * width}, 0f) : new BasicStroke(width);
    }

    /**
     * The actors where they start: a body filled, with its path (a thin line, an arrow head at
     * the end of each pass), a door or an obstacle outlined with the time it closes or appears.
     */
    private void drawActors(Graphics2D g, View v, List<ActorSpec> actors) {
        Font font = new Font(Font.SANS_SERIF, Font.PLAIN, LEGEND_FONT_PX - 1);
        g.setFont(font);
        for (ActorSpec a : actors) {
            List<Point2d> path = a.path();
            if (a.moves()) {
                Path2D.Double line = new Path2D.Double();
                line.moveTo(v.px(path.get(0).xM()), v.py(path.get(0).yM()));
                for (int i = 1; i < path.size(); i++) {
                    line.lineTo(v.px(path.get(i).xM()), v.py(path.get(i).yM()));
                }
                if (a.repeat() == ActorSpec.Repeat.LOOP) {
                    line.closePath();
                }
                g.setColor(ACTOR_PATH);
                g.setStroke(new BasicStroke(1.5f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_ROUND, 10f, new float[] {3f, 3f}, 0f));
                g.draw(line);
                Point2d from = path.get(path.size() - 2);
                Point2d to = path.get(path.size() - 1);
                double ang = Math.atan2(-(to.yM() - from.yM()), to.xM() - from.xM());
                double tx = v.px(to.xM());
                double ty = v.py(to.yM());
                g.setStroke(new BasicStroke(1.5f));
                g.draw(new Line2D.Double(tx, ty, tx - 8 * Math.cos(ang - 0.4), ty - 8 * Math.sin(ang - 0.4)));
                g.draw(new Line2D.Double(tx, ty, tx - 8 * Math.cos(ang + 0.4), ty - 8 * Math.sin(ang + 0.4)));
            }
            Point2d at = path.get(0);
            java.awt.Shape outline = outline(v, a.shape(), at);
            String label = a.name() + switch (a.kind()) {
                case BODY -> a.moves() ? String.format(java.util.Locale.ROOT, " %.1f m/s", a.speedMps()) : "";
                case DOOR -> String.format(java.util.Locale.ROOT, " closes at %.0f s", a.appearAtS());
                case OBSTACLE -> String.format(java.util.Locale.ROOT, " appears at %.0f s", a.appearAtS());
            };
            if (a.kind() == ActorSpec.Kind.BODY) {
                g.setColor(ACTOR);
                g.fill(outline);
            } else {
                g.setColor(ACTOR);
                g.setStroke(new BasicStroke(2f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_ROUND, 10f, new float[] {4f, 3f}, 0f));
                g.draw(outline);
            }
            g.setColor(ACTOR.darker());
            java.awt.Rectangle r = outline.getBounds();
            g.drawString(label, r.x + r.width + 3, r.y + r.height / 2 + 4);
        }
    }

    private static java.awt.Shape outline(View v, ActorShape shape, Point2d at) {
        double cx = v.px(at.xM());
        double cy = v.py(at.yM());
        if (shape instanceof ActorShape.Circle c) {
            double r = c.radiusM() * v.scale();
            return new Ellipse2D.Double(cx - r, cy - r, 2 * r, 2 * r);
        }
        ActorShape.Box b = (ActorShape.Box) shape;
        double w = b.widthM() * v.scale();
        double h = b.heightM() * v.scale();
        return new java.awt.geom.Rectangle2D.Double(cx - w / 2, cy - h / 2, w, h);
    }

    /** The legend's entries: one line per kind of thing drawn; kind 0 line, 1 dashed, 2 cross, 3 circle, 4 disc, 5 box. */
    private record Legend(List<String> labels, List<Color> colours, List<Integer> kinds) {
        int height() {
            return labels.size() * (LEGEND_FONT_PX + 4) + 8;
        }

        int width(Font font) {
            java.awt.font.FontRenderContext frc = new java.awt.font.FontRenderContext(null, true, true);
            double textW = 0;
            for (String l : labels) {
                textW = Math.max(textW, font.getStringBounds(l, frc).getWidth());
            }
            return (int) Math.ceil(textW) + 40;
        }

        void add(String label, Color colour, int kind) {
            labels.add(label);
            colours.add(colour);
            kinds.add(kind);
        }
    }

    private static Legend legend(boolean truePath, boolean believedPath, boolean markers, List<ActorSpec> actors) {
        Legend legend = new Legend(new ArrayList<>(), new ArrayList<>(), new ArrayList<>());
        if (truePath) {
            legend.add("true path (ground truth)", PATH, 0);
        }
        if (believedPath) {
            legend.add("believed path (odometry)", BELIEVED, 1);
        }
        if (markers) {
            legend.add("deadline missed", MARKER, 2);
        }
        if (actors.stream().anyMatch(ActorSpec::moves)) {
            legend.add("person or body at its start, its path", ACTOR, 4);
        }
        if (actors.stream().anyMatch(a -> a.kind() != ActorSpec.Kind.BODY)) {
            legend.add("door or obstacle, from the time shown", ACTOR, 5);
        }
        legend.add("waypoint (tolerance)", WAYPOINT, 3);
        legend.add("finish", FINISH, 3);
        return legend;
    }

    /** The legend in the panel, its top left corner at ({@code x0}, {@code y0}). */
    private void drawLegend(Graphics2D g, Legend legend, Font font, int x0, int y0) {
        g.setFont(font);
        int line = LEGEND_FONT_PX + 4;
        int boxW = legend.width(font);
        g.setColor(Color.GRAY);
        g.setStroke(new BasicStroke(1f));
        g.drawRect(x0, y0, boxW, legend.height());
        List<String> labels = legend.labels();
        for (int i = 0; i < labels.size(); i++) {
            int cy = y0 + 4 + i * line + line / 2;
            int kind = legend.kinds().get(i);
            g.setColor(legend.colours().get(i));
            switch (kind) {
                case 0, 1 -> {
                    g.setStroke(stroke(kind == 1));
                    g.draw(new Line2D.Double(x0 + 6, cy, x0 + 30, cy));
                }
                case 2 -> {
                    g.setStroke(new BasicStroke(1.5f));
                    g.draw(new Line2D.Double(x0 + 13, cy - 5, x0 + 23, cy + 5));
                    g.draw(new Line2D.Double(x0 + 13, cy + 5, x0 + 23, cy - 5));
                }
                case 4 -> g.fill(new Ellipse2D.Double(x0 + 12, cy - 6, 12, 12));
                case 5 -> {
                    g.setStroke(new BasicStroke(2f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_ROUND, 10f, new float[] {4f, 3f}, 0f));
                    g.draw(new java.awt.geom.Rectangle2D.Double(x0 + 10, cy - 5, 16, 10));
                }
                default -> {
                    g.setStroke(new BasicStroke(1.5f));
                    g.draw(new Ellipse2D.Double(x0 + 12, cy - 6, 12, 12));
                }
            }
            g.setColor(Color.BLACK);
            g.drawString(labels.get(i), x0 + 36, cy + LEGEND_FONT_PX / 2 - 1);
        }
    }

    /** A 1 m scale bar in the panel, its line at ({@code x0}, {@code y}). */
    private void drawScaleBar(Graphics2D g, int x0, int y) {
        double len = pixelsPerM;
        g.setColor(Color.BLACK);
        g.setStroke(new BasicStroke(2f));
        g.draw(new Line2D.Double(x0, y, x0 + len, y));
        g.draw(new Line2D.Double(x0, y - 5, x0, y + 3));
        g.draw(new Line2D.Double(x0 + len, y - 5, x0 + len, y + 3));
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, LEGEND_FONT_PX));
        g.drawString("1 m", (float) (x0 + len / 2 - 10), y - 7);
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
