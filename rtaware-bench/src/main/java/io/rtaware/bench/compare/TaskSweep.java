package io.rtaware.bench.compare;

import io.rtaware.bench.load.BenchSpec;
import io.rtaware.bench.load.BusyWork;
import io.rtaware.core.conditions.Conditions;
import io.rtaware.core.conditions.StaticConditions;
import io.rtaware.core.monitor.ThreadSetup;
import io.rtaware.core.output.FigureText;
import io.rtaware.core.output.Palette;
import io.rtaware.core.time.MonotonicSleeper;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.PrintStream;
import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
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
    private static final int CAPTION_LINE = 18;
    private static final int CAPTION_MARGIN = 10;
    private static final Font CAPTION_FONT = new Font(Font.SANS_SERIF, Font.PLAIN, 12);

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
    /** Rows asked for but not run, by task count. */
    private final Map<Integer, List<String>> leftOut = new LinkedHashMap<>();

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
            CompareRun run = comparison.forTasks(count);
            if (!run.leftOut().isEmpty()) {
                leftOut(count, run.leftOut());
            }
            for (RunResult r : run.run()) {
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
     * @param rows the rows, labels of {@link CompareRun#ROWS}
     * @param workers pool size
     * @param sleeper how rtaware's threaded executor sleeps its task threads (null: they park)
     * @param threadSetup run on rtaware's task threads and workers, or null
     * @return how each count's comparison is built
     */
    public static Comparison comparison(java.util.function.IntFunction<List<BenchSpec>> specsOf, BusyWork work,
                                        long measuredNs, long segmentNs, PrintStream progress,
                                        List<String> rows, int workers, MonotonicSleeper sleeper,
                                        ThreadSetup threadSetup) {
        return tasks -> new CompareRun(specsOf.apply(tasks), work, measuredNs, segmentNs, progress, rows, workers,
                sleeper, threadSetup);
    }

    /**
     * @param tasks a task count
     * @param run an executor's row of the comparison at that count
     */
    void add(int tasks, RunResult run) {
        points.add(new Point(tasks, run));
    }

    /**
     * @param tasks a task count
     * @param rows the rows asked for that its comparison left out
     */
    void leftOut(int tasks, List<String> rows) {
        leftOut.put(tasks, List.copyOf(rows));
    }

    /**
     * @return one line per task count at which rows asked for were not run, e.g. {@code not run at
     *     10000 tasks: rtaware, stpe, park-loop (a thread per task, more than 1000 per core)}
     */
    public List<String> leftOutLines() {
        return leftOut.entrySet().stream().map(e -> String.format(Locale.ROOT,
                "not run at %d tasks: %s (a thread per task, more than %d per core)", e.getKey(),
                String.join(", ", e.getValue()), CompareRun.THREAD_PER_TASK_LIMIT_PER_CORE)).toList();
    }

    /**
     * The conditions a figure shows under its plots.
     *
     * @param conditions measured over the sweep
     * @param date when it ran
     * @return the lines: the host, the JVM, rtaware's verdict on the machine's load, the date
     */
    public static List<String> caption(Conditions conditions, Instant date) {
        StaticConditions setup = conditions.setup();
        String virtual = Boolean.TRUE.equals(setup.virtualized())
                ? ", virtual" + (setup.hypervisor() == null ? "" : " (" + setup.hypervisor() + ")") : "";
        return List.of(
                String.format(Locale.ROOT, "host: %s, %d CPUs%s, %s", setup.cpuModel(), setup.logicalCpus(), virtual,
                        setup.kernel()),
                "JVM: " + setup.jvmVendor() + " " + setup.jvmVersion() + ", " + String.join(", ", setup.collectors()),
                conditions.summaryLine(),
                "run " + DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm 'UTC'", Locale.ROOT)
                        .format(date.atZone(ZoneOffset.UTC)));
    }

    /** @return every executor at every task count */
    public List<Point> points() {
        return List.copyOf(points);
    }

    /** @return the table: one line per executor and task count, then the rows left out */
    public String table() {
        StringBuilder sb = new StringBuilder(String.format(Locale.ROOT, "%-14s %7s %9s %8s | %10s %10s%n",
                "executor", "tasks", "releases", "misses%", "late p99", "p99.9"));
        for (Point p : points) {
            sb.append(String.format(Locale.ROOT, "%-14s %7d %9d %8.2f | %8.1fus %8.1fus%n", p.run().executor(),
                    p.tasks(), p.run().releases(), p.missPct(), p.run().latenessUs().p99(),
                    p.run().latenessUs().p999()));
        }
        leftOutLines().forEach(line -> sb.append(line).append(System.lineSeparator()));
        return sb.toString();
    }

    /**
     * Draws the two plots, one above the other, and under them the caption and a line for each
     * task count at which rows were left out, as one image (write it with {@code OutputFiles.png}).
     *
     * @param subtitle what was run (period, work, machine), shown in the titles
     * @param caption the conditions ({@link #caption}), one line each
     * @return the image
     */
    public BufferedImage plot(String subtitle, List<String> caption) {
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
        List<String> given = new ArrayList<>(leftOutLines());
        given.addAll(caption);
        List<String> notes = wrap(given, new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB).createGraphics()
                .getFontMetrics(CAPTION_FONT), WIDTH - 2 * CAPTION_MARGIN);
        BufferedImage image = new BufferedImage(WIDTH, 2 * HEIGHT + CAPTION_MARGIN + notes.size() * CAPTION_LINE,
                BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        misses.paint(g, WIDTH, HEIGHT);
        g.translate(0, HEIGHT);
        lateness.paint(g, WIDTH, HEIGHT);
        g.translate(0, HEIGHT);
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, WIDTH, image.getHeight() - 2 * HEIGHT);
        g.setColor(Color.BLACK);
        g.setFont(CAPTION_FONT);
        for (int i = 0; i < notes.size(); i++) {
            g.drawString(notes.get(i), CAPTION_MARGIN, (i + 1) * CAPTION_LINE);
        }
        g.dispose();
        return image;
    }

    /**
     * Breaks each line at spaces so that it fits the width (a word wider than it stays whole).
     *
     * @param lines the lines
     * @param metrics the font's
     * @param widthPx the width
     * @return the lines as drawn
     */
    static List<String> wrap(List<String> lines, FontMetrics metrics, int widthPx) {
        List<String> wrapped = new ArrayList<>();
        for (String line : lines) {
            StringBuilder current = new StringBuilder();
            for (String word : line.split(" ")) {
                String candidate = current.length() == 0 ? word : current + " " + word;
                if (current.length() > 0 && metrics.stringWidth(candidate) > widthPx) {
                    wrapped.add(current.toString());
                    current.setLength(0);
                    current.append("    ").append(word);
                } else {
                    current.setLength(0);
                    current.append(candidate);
                }
            }
            wrapped.add(current.toString());
        }
        return wrapped;
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
