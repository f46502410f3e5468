package io.rtaware.bench.compare;

import io.rtaware.bench.load.BenchSpec;
import io.rtaware.bench.load.BusyWork;
import io.rtaware.core.monitor.ThreadSetup;
import io.rtaware.core.output.FigureText;
import io.rtaware.core.output.Palette;
import io.rtaware.core.time.MonotonicSleeper;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.PrintStream;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * {@code bench --sweep-tasks 10,100,1000,10000}: one interleaved comparison ({@link CompareRun})
 * per task count, so a user sees where each executor stops scaling on their machine: a table of
 * misses and p99/p99.9 lateness per executor and task count, and one PNG with two XChart plots
 * against the task count (log scale): misses in % of releases, and p99 and p99.9 lateness.
 *
 * <p>Not thread-safe: one thread runs the sweep.
 */
public final class TaskSweep {

    private static final int WIDTH = 900;
    private static final int HEIGHT = 420;

    /**
     * One executor at one task count.
     *
     * @param tasks the task count
     * @param run the executor's row of that comparison
     */
    public record Point(int tasks, RunResult run) {

        /** @return misses in % of releases */
        public double missPct() {
            return run.releases() == 0 ? 0 : 100.0 * run.misses() / run.releases();
        }
    }

    private final List<Point> points = new ArrayList<>();

    /**
     * Runs one comparison per task count.
     *
     * @param counts the task counts, ascending
     * @param comparison builds the comparison of a task set
     * @param progress where to print one line per task count
     * @return this sweep, with its points
     * @throws InterruptedException if interrupted
     */
    public TaskSweep run(List<Integer> counts, Comparison comparison, PrintStream progress)
            throws InterruptedException {
        for (int count : counts) {
            progress.printf("sweep: %d task(s)%n", count);
            for (RunResult r : comparison.forTasks(count).run()) {
                add(count, r);
            }
        }
        return this;
    }

    /** Builds the comparison for a task count. */
    @FunctionalInterface
    public interface Comparison {
        /**
         * @param tasks the task count
         * @return the comparison to run
         */
        CompareRun forTasks(int tasks);
    }

    /**
     * @param specsOf the task set for a count
     * @param work the calibrated busy loop
     * @param measuredNs measured time per executor
     * @param segmentNs segment length
     * @param progress progress lines
     * @param family the executors
     * @param workers pool size
     * @param sleeper how rtaware's threaded executor sleeps its task threads (null: they park)
     * @param threadSetup run on rtaware's task threads and workers, or null
     * @return how each count's comparison is built
     */
    public static Comparison comparison(java.util.function.IntFunction<List<BenchSpec>> specsOf, BusyWork work,
                                        long measuredNs, long segmentNs, PrintStream progress,
                                        CompareRun.Family family, int workers, MonotonicSleeper sleeper,
                                        ThreadSetup threadSetup) {
        return tasks -> new CompareRun(specsOf.apply(tasks), work, measuredNs, segmentNs, progress, family, workers,
                sleeper, threadSetup);
    }

    /**
     * @param tasks a task count
     * @param run an executor's row of the comparison at that count
     */
    void add(int tasks, RunResult run) {
        points.add(new Point(tasks, run));
    }

    /** @return every executor at every task count */
    public List<Point> points() {
        return List.copyOf(points);
    }

    /** @return the table: one line per executor and task count */
    public String table() {
        StringBuilder sb = new StringBuilder(String.format(Locale.ROOT, "%-14s %7s %9s %8s | %10s %10s%n",
                "executor", "tasks", "releases", "misses%", "late p99", "p99.9"));
        for (Point p : points) {
            sb.append(String.format(Locale.ROOT, "%-14s %7d %9d %8.2f | %8.1fus %8.1fus%n", p.run().executor(),
                    p.tasks(), p.run().releases(), p.missPct(), p.run().latenessUs().p99(),
                    p.run().latenessUs().p999()));
        }
        return sb.toString();
    }

    /**
     * Draws the two plots, one above the other, as one image (write it with
     * {@code OutputFiles.png}).
     *
     * @param subtitle what was run (period, work, machine), shown in the titles
     * @return the image
     */
    public BufferedImage plot(String subtitle) {
        Map<String, List<Point>> byExecutor = new LinkedHashMap<>();
        for (Point p : points) {
            byExecutor.computeIfAbsent(p.run().executor(), k -> new ArrayList<>()).add(p);
        }
        XYChart misses = chart("Misses against task count (" + subtitle + ")", "misses (% of releases)", false);
        XYChart lateness = chart("Release lateness against task count (" + subtitle + ")", "lateness (us, log)", true);
        int colour = 0;
        for (Map.Entry<String, List<Point>> e : byExecutor.entrySet()) {
            double[] x = e.getValue().stream().mapToDouble(Point::tasks).toArray();
            Color c = Palette.colour(colour++);
            line(misses.addSeries(e.getKey(), x, e.getValue().stream().mapToDouble(Point::missPct).toArray()), c, false);
            line(lateness.addSeries(e.getKey() + " p99", x,
                    e.getValue().stream().mapToDouble(p -> Math.max(1, p.run().latenessUs().p99())).toArray()), c, false);
            line(lateness.addSeries(e.getKey() + " p99.9", x,
                    e.getValue().stream().mapToDouble(p -> Math.max(1, p.run().latenessUs().p999())).toArray()), c, true);
        }
        for (XYChart chart : List.of(misses, lateness)) {
            FigureText.fitTitle(chart.getStyler().getChartTitleFont(), chart.getStyler()::setChartTitleFont,
                    () -> BitmapEncoder.getBufferedImage(chart), chart.getStyler().getChartPadding());
        }
        BufferedImage image = new BufferedImage(WIDTH, 2 * HEIGHT, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        misses.paint(g, WIDTH, HEIGHT);
        g.translate(0, HEIGHT);
        lateness.paint(g, WIDTH, HEIGHT);
        g.dispose();
        return image;
    }

    private static XYChart chart(String title, String yTitle, boolean logY) {
        XYChart chart = new XYChartBuilder().width(WIDTH).height(HEIGHT).title(title)
                .xAxisTitle("tasks (log)").yAxisTitle(yTitle).build();
        Styler styler = chart.getStyler();
        styler.setChartTitleFont(new Font(Font.SANS_SERIF, Font.BOLD, 14));
        styler.setChartBackgroundColor(Color.WHITE);
        styler.setPlotBackgroundColor(Color.WHITE);
        styler.setLegendPosition(Styler.LegendPosition.OutsideE);
        styler.setAntiAlias(true);
        chart.getStyler().setXAxisLogarithmic(true);
        chart.getStyler().setYAxisLogarithmic(logY);
        chart.getStyler().setPlotGridLinesColor(new Color(0xDDDDDD));
        if (!logY) {
            chart.getStyler().setYAxisMin(0.0);
        }
        return chart;
    }

    private static void line(XYSeries series, Color colour, boolean dashed) {
        series.setLineColor(colour);
        series.setMarkerColor(colour);
        series.setMarker(SeriesMarkers.CIRCLE);
        series.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Line);
        if (dashed) {
            series.setLineStyle(new BasicStroke(1.5f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f,
                    new float[] {6f, 4f}, 0f));
        }
    }
}
