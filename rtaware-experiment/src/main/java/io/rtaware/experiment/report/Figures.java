package io.rtaware.experiment.report;

import io.rtaware.core.output.FigureText;
import io.rtaware.core.output.OutputFiles;
import io.rtaware.core.output.Palette;
import io.rtaware.experiment.ExperimentSummary;
import io.rtaware.experiment.ExperimentSummary.SetSummary;
import io.rtaware.experiment.PeriodSet;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Point2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.CategoryChart;
import org.knowm.xchart.CategoryChartBuilder;
import org.knowm.xchart.VectorGraphicsEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.internal.chartpart.Chart;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * Draws the experiment's figures with XChart, each as PNG and SVG: missed deadlines per task
 * per set (the paper's Fig. 7), per set over all four tasks (Fig. 8), box plots of run time and
 * distance to the finish per set (with every run as a dot), and every run's path over the course.
 * Every figure takes its colours from {@link Palette}, keeps its legend outside the plot, and
 * shrinks a title that would not fit ({@link #fitTitle}).
 */
public final class Figures {

    /** Fig. 7 of the paper: missed-deadline % per task, grouped by set. */
    public static final String FIG7 = "fig7-task-misses";
    /** Fig. 8 of the paper: missed-deadline % of all four tasks per set. */
    public static final String FIG8 = "fig8-set-misses";
    /** Box plot of run time per set (completed runs). */
    public static final String RUNTIME_BOX = "runtime-box";
    /** Box plot of distance to the finish per set. */
    public static final String DISTANCE_BOX = "distance-box";
    /** Every run's path, one colour per set. */
    public static final String TRAJECTORIES = "trajectories";

    private static final int WIDTH = 1000;
    /** The fewest values a set needs for a box. */
    static final int BOX_FROM = 3;
    private static final double BOX_HALF_WIDTH = 0.25;
    private static final double DOT_SPREAD = 0.15;
    private static final int HEIGHT = 600;
    private static final Color TRANSPARENT = new Color(0, 0, 0, 0);

    private Figures() {
    }

    /**
     * @param index a zero-based set or task index
     * @return its colour, from the one palette of every figure ({@link Palette})
     */
    public static Color colour(int index) {
        return Palette.colour(index);
    }

    /**
     * Writes {@code fig7-task-misses.png/.svg}.
     *
     * @param summary the experiment's summary
     * @param dir the output folder
     * @throws IOException if writing fails
     */
    public static void taskMisses(ExperimentSummary summary, Path dir) throws IOException {
        CategoryChart chart = categoryChart("Missed deadlines per task (cf. paper Fig. 7)", "missed deadlines (% of releases)");
        List<String> sets = setLabels(summary);
        for (int t = 0; t < PeriodSet.TASKS.size(); t++) {
            String task = PeriodSet.TASKS.get(t);
            List<Double> pct = summary.sets().stream().map(s -> valueOrZero(s.misses().get(task).missPct())).toList();
            chart.addSeries(task, sets, pct).setFillColor(colour(t));
        }
        save(chart, dir, FIG7);
    }

    /**
     * Writes {@code fig8-set-misses.png/.svg}.
     *
     * @param summary the experiment's summary
     * @param dir the output folder
     * @throws IOException if writing fails
     */
    public static void setMisses(ExperimentSummary summary, Path dir) throws IOException {
        CategoryChart chart = categoryChart("Missed deadlines of all four tasks per set (cf. paper Fig. 8)",
                "missed deadlines (% of releases)");
        List<Double> pct = summary.sets().stream()
                .map(s -> valueOrZero(s.misses().get(ExperimentSummary.ALL_TASKS).missPct())).toList();
        chart.addSeries("waypoint + obstacle + occupancy + planner", setLabels(summary), pct).setFillColor(colour(0));
        save(chart, dir, FIG8);
    }

    /**
     * Writes a box plot per set of one quantity, with every value drawn as a dot beside its box: a
     * set of fewer than three values has no box (its quartiles would say nothing), only its dots,
     * so a single run still shows. Each set has its colour and its legend entry with its count.
     *
     * @param samples per set label, the values
     * @param title the chart's title
     * @param yTitle the y axis title with its unit
     * @param dir the output folder
     * @param name the file name without extension
     * @throws IOException if writing fails
     */
    public static void boxPlot(Map<String, double[]> samples, String title, String yTitle, Path dir, String name)
            throws IOException {
        if (samples.values().stream().allMatch(v -> v.length == 0)) {
            noData(title, dir, name);
            return;
        }
        save(boxChart(samples, title, yTitle), dir, name);
    }

    /** The box plot of {@link #boxPlot} as a chart: set i (from 1) at x = i, its dots spread across the box. */
    static XYChart boxChart(Map<String, double[]> samples, String title, String yTitle) {
        XYChart chart = new XYChartBuilder().width(WIDTH).height(HEIGHT).title(title)
                .xAxisTitle("experiment set; box: quartiles and median, whiskers to the extremes (3 runs or more);"
                        + " dots: each run").yAxisTitle(yTitle).build();
        style(chart.getStyler());
        chart.getStyler().setLegendPosition(Styler.LegendPosition.OutsideE);
        chart.getStyler().setXAxisTicksVisible(false);
        chart.getStyler().setMarkerSize(9);
        int colour = 0;
        int x = 0;
        for (Map.Entry<String, double[]> e : samples.entrySet()) {
            double[] values = e.getValue().clone();
            Color c = colour(colour++);
            if (values.length == 0) {
                continue;
            }
            x++;
            java.util.Arrays.sort(values);
            if (values.length >= BOX_FROM) {
                box(chart, e.getKey(), x, values, c);
            }
            double[] xs = new double[values.length];
            double spread = Math.min(DOT_SPREAD, DOT_SPREAD * (values.length - 1) / 10.0);
            for (int i = 0; i < values.length; i++) {
                xs[i] = values.length == 1 ? x : x - spread + 2 * spread * i / (values.length - 1);
            }
            XYSeries dots = chart.addSeries(e.getKey() + " (n=" + values.length + ")", xs, values);
            dots.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
            dots.setMarker(SeriesMarkers.CIRCLE).setMarkerColor(c);
        }
        chart.getStyler().setXAxisMin(0.4).setXAxisMax(x + 0.6);
        return chart;
    }

    /** A box from the lower to the upper quartile with the median across it, whiskers to the extremes. */
    private static void box(XYChart chart, String set, int x, double[] sorted, Color c) {
        org.apache.commons.math3.stat.descriptive.rank.Percentile p = new org.apache.commons.math3.stat.descriptive.rank.Percentile();
        p.setData(sorted);
        double q1 = p.evaluate(25);
        double median = p.evaluate(50);
        double q3 = p.evaluate(75);
        double l = x - BOX_HALF_WIDTH;
        double r = x + BOX_HALF_WIDTH;
        segment(chart, set + " box", new double[] {l, r, r, l, l}, new double[] {q1, q1, q3, q3, q1}, c, 1.5f);
        segment(chart, set + " median", new double[] {l, r}, new double[] {median, median}, c, 3f);
        segment(chart, set + " low", new double[] {x, x}, new double[] {sorted[0], q1}, c, 1.5f);
        segment(chart, set + " high", new double[] {x, x}, new double[] {q3, sorted[sorted.length - 1]}, c, 1.5f);
    }

    private static void segment(XYChart chart, String name, double[] xs, double[] ys, Color c, float width) {
        XYSeries s = chart.addSeries(name, xs, ys);
        s.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Line);
        s.setMarker(SeriesMarkers.NONE).setLineColor(c).setLineStyle(new BasicStroke(width));
        s.setShowInLegend(false);
    }

    /**
     * Writes {@code trajectories.png/.svg}: every path, one colour per set, true (solid) and
     * believed by the robot's odometry (dashed) where the run recorded it, waypoints as black
     * diamonds, over the background's picture when it has one (PNG only; the SVG has the paths),
     * with a legend and (PNG) a 1 m scale bar.
     *
     * @param summary the experiment's summary (set names and order)
     * @param paths the runs' paths
     * @param background the course
     * @param dir the output folder
     * @throws IOException if writing fails
     */
    public static void trajectories(ExperimentSummary summary, List<Trajectory> paths, MapBackground background, Path dir)
            throws IOException {
        WorldBounds bounds = background.image().isPresent() ? background.bounds() : null;
        for (Trajectory t : paths) {
            WorldBounds b = t.bounds();
            bounds = b == null ? bounds : b.union(bounds);
        }
        for (Point2D.Double w : background.waypoints()) {
            WorldBounds b = new WorldBounds(w.x - 0.01, w.y - 0.01, w.x + 0.01, w.y + 0.01);
            bounds = b.union(bounds);
        }
        if (bounds == null) {
            noData("Paths driven: no trajectory.csv found", dir, TRAJECTORIES);
            return;
        }
        WorldBounds frame = background.image().isPresent() ? bounds : bounds.grow(0.05 * Math.max(bounds.widthM(), bounds.heightM()));
        XYChart chart = trajectoryChart(summary, paths, background, frame, HEIGHT);
        // Second pass: make one metre as long on both axes.
        BufferedImage probe = new BufferedImage(WIDTH, HEIGHT, BufferedImage.TYPE_INT_ARGB);
        chart.paint(probe.createGraphics(), WIDTH, HEIGHT);
        double pxPerMx = (chart.getScreenXFromChart(frame.maxXM()) - chart.getScreenXFromChart(frame.minXM())) / frame.widthM();
        double plotHeightPx = chart.getScreenYFromChart(frame.minYM()) - chart.getScreenYFromChart(frame.maxYM());
        int height = (int) Math.round(HEIGHT + pxPerMx * frame.heightM() - plotHeightPx);
        height = Math.max(300, Math.min(2000, height));
        chart = trajectoryChart(summary, paths, background, frame, height);
        saveSvg(chart, dir, TRAJECTORIES);
        BufferedImage out = new BufferedImage(WIDTH, height, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = out.createGraphics();
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, WIDTH, height);
        if (background.image().isPresent()) {
            BufferedImage overlay = new BufferedImage(WIDTH, height, BufferedImage.TYPE_INT_ARGB);
            chart.getStyler().setChartBackgroundColor(TRANSPARENT);
            chart.getStyler().setPlotBackgroundColor(TRANSPARENT);
            chart.paint(overlay.createGraphics(), WIDTH, height);
            WorldBounds mb = background.bounds();
            int x0 = (int) Math.round(chart.getScreenXFromChart(mb.minXM()));
            int x1 = (int) Math.round(chart.getScreenXFromChart(mb.maxXM()));
            int y0 = (int) Math.round(chart.getScreenYFromChart(mb.maxYM()));
            int y1 = (int) Math.round(chart.getScreenYFromChart(mb.minYM()));
            g.setRenderingHint(RenderingHints.KEY_INTERPOLATION, RenderingHints.VALUE_INTERPOLATION_NEAREST_NEIGHBOR);
            g.drawImage(background.image().get(), x0, y0, x1 - x0, y1 - y0, null);
            g.drawImage(overlay, 0, 0, null);
        } else {
            chart.paint(g, WIDTH, height);
        }
        drawScaleBar(g, chart, frame);
        g.dispose();
        OutputFiles.write(dir.resolve(TRAJECTORIES + ".png"), OutputFiles.png(out));
    }

    /** A 1 m scale bar in the plot's lower left corner, at the chart's own scale. */
    private static void drawScaleBar(Graphics2D g, XYChart chart, WorldBounds frame) {
        double x0 = chart.getScreenXFromChart(frame.minXM() + 0.02 * frame.widthM());
        double x1 = chart.getScreenXFromChart(frame.minXM() + 0.02 * frame.widthM() + 1.0);
        double y = chart.getScreenYFromChart(frame.minYM() + 0.04 * frame.heightM());
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setColor(new Color(255, 255, 255, 220));
        g.fillRect((int) x0 - 4, (int) y - 22, (int) (x1 - x0) + 8, 30);
        g.setColor(Color.BLACK);
        g.setStroke(new BasicStroke(2f));
        g.draw(new java.awt.geom.Line2D.Double(x0, y, x1, y));
        g.draw(new java.awt.geom.Line2D.Double(x0, y - 5, x0, y + 3));
        g.draw(new java.awt.geom.Line2D.Double(x1, y - 5, x1, y + 3));
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        g.drawString("1 m", (float) ((x0 + x1) / 2 - 10), (float) y - 8);
    }

    private static XYChart trajectoryChart(ExperimentSummary summary, List<Trajectory> paths, MapBackground background,
                                           WorldBounds frame, int height) {
        XYChart chart = new XYChartBuilder().width(WIDTH).height(height)
                .title("Paths driven, one colour per set: true (solid), believed by odometry (dashed)")
                .xAxisTitle("x (m)").yAxisTitle("y (m)").build();
        style(chart.getStyler());
        chart.getStyler().setXAxisMin(frame.minXM()).setXAxisMax(frame.maxXM());
        chart.getStyler().setYAxisMin(frame.minYM()).setYAxisMax(frame.maxYM());
        chart.getStyler().setLegendPosition(Styler.LegendPosition.OutsideE);
        chart.getStyler().setDefaultSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Line);
        chart.getStyler().setDecimalPattern("0.0");
        List<SetSummary> sets = summary.sets();
        for (int i = 0; i < sets.size(); i++) {
            SetSummary set = sets.get(i);
            boolean first = true;
            for (Trajectory t : paths) {
                if (t.set() != set.set() || t.xM().length == 0) {
                    continue;
                }
                XYSeries s = chart.addSeries(first ? set.name() + " true" : set.name() + " run " + t.run(), t.xM(), t.yM());
                s.setMarker(SeriesMarkers.NONE).setLineColor(colour(i)).setLineStyle(new BasicStroke(1.5f));
                s.setShowInLegend(first);
                if (t.believedXM().length > 1) {
                    XYSeries b = chart.addSeries(first ? set.name() + " believed (odometry)"
                            : set.name() + " run " + t.run() + " believed", t.believedXM(), t.believedYM());
                    b.setMarker(SeriesMarkers.NONE).setLineColor(colour(i)).setLineStyle(new BasicStroke(1.0f,
                            BasicStroke.CAP_BUTT, BasicStroke.JOIN_ROUND, 10f, new float[] {6f, 4f}, 0f));
                    b.setShowInLegend(first);
                }
                first = false;
            }
        }
        List<Point2D.Double> w = background.waypoints();
        if (!w.isEmpty()) {
            XYSeries s = chart.addSeries("waypoints (last = finish)", w.stream().mapToDouble(p -> p.x).toArray(),
                    w.stream().mapToDouble(p -> p.y).toArray());
            s.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
            s.setMarker(SeriesMarkers.DIAMOND).setMarkerColor(Color.BLACK);
        }
        fitTitle(chart);
        return chart;
    }

    private static CategoryChart categoryChart(String title, String yTitle) {
        CategoryChart chart = new CategoryChartBuilder().width(WIDTH).height(HEIGHT).title(title)
                .xAxisTitle("experiment set").yAxisTitle(yTitle).build();
        style(chart.getStyler());
        chart.getStyler().setLegendPosition(Styler.LegendPosition.OutsideE);
        chart.getStyler().setYAxisMin(0.0);
        chart.getStyler().setLabelsVisible(true);
        chart.getStyler().setLabelsFont(new Font(Font.SANS_SERIF, Font.BOLD, 11));
        chart.getStyler().setLabelsPosition(1.0);
        chart.getStyler().setLabelsFontColorAutomaticEnabled(true);
        chart.getStyler().setDecimalPattern("0.0#");
        return chart;
    }

    static void style(Styler styler) {
        styler.setChartTitleFont(new Font(Font.SANS_SERIF, Font.BOLD, 18));
        styler.setLegendFont(new Font(Font.SANS_SERIF, Font.PLAIN, 13));
        styler.setChartBackgroundColor(Color.WHITE);
        styler.setPlotBackgroundColor(Color.WHITE);
        styler.setLegendBorderColor(Color.LIGHT_GRAY);
        styler.setAntiAlias(true);
        if (styler instanceof org.knowm.xchart.style.AxesChartStyler axes) {
            axes.setAxisTitleFont(new Font(Font.SANS_SERIF, Font.PLAIN, 14));
            axes.setAxisTickLabelsFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
            axes.setPlotGridLinesColor(new Color(0xDDDDDD));
        }
    }

    private static List<String> setLabels(ExperimentSummary summary) {
        List<String> labels = new ArrayList<>();
        for (SetSummary s : summary.sets()) {
            labels.add(s.name() + " (" + String.join("/", s.periodsMs().values().stream().map(String::valueOf).toList()) + ")");
        }
        return labels;
    }

    private static double valueOrZero(Double v) {
        return v == null ? 0.0 : v;
    }

    static void save(Chart<?, ?> chart, Path dir, String name) throws IOException {
        fitTitle(chart);
        OutputFiles.write(dir.resolve(name + ".png"), OutputFiles.png(BitmapEncoder.getBufferedImage(chart)));
        saveSvg(chart, dir, name);
    }

    /**
     * Shrinks the chart's title font until the title, as the chart paints it (centred over the
     * plot, which a legend beside it moves), stays clear of the chart's padding on both sides.
     *
     * @param chart a chart with its title and series set
     */
    static void fitTitle(Chart<?, ?> chart) {
        Styler styler = chart.getStyler();
        FigureText.fitTitle(styler.getChartTitleFont(), styler::setChartTitleFont,
                () -> BitmapEncoder.getBufferedImage(chart), styler.getChartPadding());
    }

    /**
     * The SVG is a courtesy copy: when it cannot be written (as while the JVM shuts down after
     * Ctrl-C, when the vector library cannot start) the PNG stands alone and a stale SVG is removed.
     */
    private static void saveSvg(Chart<?, ?> chart, Path dir, String name) throws IOException {
        Path svg = dir.resolve(name + ".svg");
        try {
            OutputFiles.write(svg, out -> VectorGraphicsEncoder.saveVectorGraphic(chart, out,
                    VectorGraphicsEncoder.VectorGraphicsFormat.SVG));
        } catch (IOException | RuntimeException | LinkageError e) {
            java.nio.file.Files.deleteIfExists(svg);
            System.err.println("rtaware: " + svg.getFileName() + " not written (" + e + "); the PNG has the same figure");
        }
    }

    static void noData(String title, Path dir, String name) throws IOException {
        BufferedImage img = new BufferedImage(WIDTH, 200, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, WIDTH, 200);
        g.setColor(Color.DARK_GRAY);
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 18));
        g.drawString(title, 20, 80);
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 14));
        g.drawString("No data to plot (see report.md for why).", 20, 120);
        g.dispose();
        OutputFiles.write(dir.resolve(name + ".png"), OutputFiles.png(img));
        java.nio.file.Files.deleteIfExists(dir.resolve(name + ".svg"));
    }
}
