package io.rtaware.experiment.report;

import io.rtaware.experiment.ExperimentSummary;
import io.rtaware.experiment.ExperimentSummary.SetSummary;
import io.rtaware.experiment.PeriodSet;
import io.rtaware.experiment.claims.PaperClaims;
import io.rtaware.experiment.stats.RateInterval;
import io.rtaware.experiment.stats.SampleStats;
import java.awt.BasicStroke;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.function.Function;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * The figures of a sweep, each as PNG and SVG: completion and collision rate, collisions and
 * near misses with their intervals beside the reaction rule's bound (period axis only), run time,
 * distance to the finish and missed deadlines per task, against the swept period (log axis;
 * {@code sweep-*}) and, when the sets differ in top speed, against the speed ({@code speed-*}).
 * One line per top speed on the period figures, one per swept period on the speed figures.
 */
public final class SweepFigures {

    /** Completion and collision rate against the period. */
    public static final String PERIOD_RATES = "sweep-rates";
    /**
     * Collision and near-miss rate against the period, each with its Wilson 95 % interval, and
     * the reaction rule's largest safe period on the same axis.
     */
    public static final String PERIOD_SAFETY = "sweep-safety";
    /** Mean run time (completed runs, SD as error bars) against the period. */
    public static final String PERIOD_RUNTIME = "sweep-runtime";
    /** Mean distance to the finish (SD as error bars) against the period. */
    public static final String PERIOD_DISTANCE = "sweep-distance";
    /** Missed deadlines per task against the period. */
    public static final String PERIOD_MISSES = "sweep-misses";
    /** The prefix of the same figures against the top speed ({@code speed-rates}, ...). */
    public static final String SPEED_PREFIX = "speed-";

    private static final int WIDTH = 1000;
    private static final int HEIGHT = 560;
    private static final float[] SOLID = null;
    /** Line patterns that tell groups (top speeds) apart where colour tells the quantity or task. */
    private static final float[][] DASHES = {SOLID, {8f, 5f}, {2f, 4f}, {12f, 4f, 2f, 4f}};

    private SweepFigures() {
    }

    /** One axis of a sweep: where a set sits on it, and how the sets on it are grouped into lines. */
    private record Axis(String title, boolean log, Function<SetSummary, Double> x, Function<SetSummary, String> line) {
    }

    /**
     * @param summary an experiment's summary
     * @return true if at least two sets have different swept periods (the period figures are drawn)
     */
    public static boolean hasPeriodAxis(ExperimentSummary summary) {
        return summary.sets().stream().map(SetSummary::sweptPeriodMs).filter(Objects::nonNull).distinct().count() >= 2;
    }

    /**
     * @param summary an experiment's summary
     * @return true if the sets differ in top speed (the speed figures are drawn)
     */
    public static boolean hasSpeedAxis(ExperimentSummary summary) {
        return summary.sets().stream().map(SetSummary::topSpeedMps).filter(Objects::nonNull).distinct().count() >= 2;
    }

    /**
     * Writes the period figures (when {@link #hasPeriodAxis}) and the speed figures (when
     * {@link #hasSpeedAxis}).
     *
     * @param summary an experiment's summary
     * @param dir the output folder
     * @throws IOException if writing fails
     */
    public static void write(ExperimentSummary summary, Path dir) throws IOException {
        String swept = summary.sweptTasks().size() == PeriodSet.TASKS.size() ? "all four tasks"
                : String.join(" + ", summary.sweptTasks());
        if (hasPeriodAxis(summary)) {
            Axis period = new Axis("period of " + swept + " (ms, log scale)", true,
                    s -> s.sweptPeriodMs() == null ? null : (double) s.sweptPeriodMs(),
                    s -> speed(s.topSpeedMps()));
            drawAll(summary, dir, period, "sweep-", "period");
        }
        if (hasSpeedAxis(summary)) {
            Axis speed = new Axis("top speed (m/s)", false, SetSummary::topSpeedMps,
                    s -> s.sweptPeriodMs() == null ? s.name() : swept + " " + s.sweptPeriodMs() + " ms");
            drawAll(summary, dir, speed, SPEED_PREFIX, "top speed");
        }
    }

    private static void drawAll(ExperimentSummary summary, Path dir, Axis axis, String prefix, String against)
            throws IOException {
        Map<String, List<SetSummary>> lines = lines(summary, axis);
        XYChart rates = chart("Completed and collided runs against the " + against, axis, "runs (%)");
        int i = 0;
        for (Map.Entry<String, List<SetSummary>> e : lines.entrySet()) {
            String suffix = lines.size() > 1 ? " (" + e.getKey() + ")" : "";
            add(rates, "completed" + suffix, e.getValue(), axis, s -> percent(s.completionRate()), s -> null, i, SOLID);
            add(rates, "collided" + suffix, e.getValue(), axis, s -> percent(s.collisionRate()), s -> null, i, DASHES[1]);
            i++;
        }
        rates.getStyler().setYAxisMin(0.0).setYAxisMax(100.0);
        Figures.save(rates, dir, prefix + "rates");
        if (axis.log()) {
            safety(summary, lines, axis, dir);
        }

        XYChart runtime = chart("Run time of the completed runs against the " + against + " (mean, SD as bars)", axis,
                "run time (s, world time)");
        XYChart distance = chart("Distance from the finish against the " + against + " (mean, SD as bars)", axis,
                "distance to finish (m)");
        i = 0;
        for (Map.Entry<String, List<SetSummary>> e : lines.entrySet()) {
            String name = lines.size() > 1 ? e.getKey() : "mean";
            add(runtime, name, e.getValue(), axis, s -> s.runTimeS().mean(), s -> sdOrZero(s.runTimeS()), i, SOLID);
            add(distance, name, e.getValue(), axis, s -> s.distanceToFinishM().mean(), s -> sdOrZero(s.distanceToFinishM()),
                    i, SOLID);
            i++;
        }
        Figures.save(runtime, dir, prefix + "runtime");
        Figures.save(distance, dir, prefix + "distance");

        XYChart misses = chart("Missed deadlines per task against the " + against, axis, "missed deadlines (% of releases)");
        int group = 0;
        for (Map.Entry<String, List<SetSummary>> e : lines.entrySet()) {
            String suffix = lines.size() > 1 ? " (" + e.getKey() + ")" : "";
            float[] dash = DASHES[group++ % DASHES.length];
            for (int t = 0; t < PeriodSet.TASKS.size(); t++) {
                String task = PeriodSet.TASKS.get(t);
                add(misses, task + suffix, e.getValue(), axis, s -> s.misses().get(task).missPct(), s -> null, t, dash);
            }
            add(misses, "all four" + suffix, e.getValue(), axis, s -> s.misses().get(ExperimentSummary.ALL_TASKS).missPct(),
                    s -> null, PeriodSet.TASKS.size() + 3, dash);
        }
        misses.getStyler().setYAxisMin(0.0);
        Figures.save(misses, dir, prefix + "misses");
    }

    /**
     * The safety figure of the period axis: per line, the collision and the near-miss rate with
     * their intervals as vertical segments, and a vertical line at each line's reaction-rule
     * bound (the largest safe period the runs' advice gave), when the runs report one.
     */
    private static void safety(ExperimentSummary summary, Map<String, List<SetSummary>> lines, Axis axis, Path dir)
            throws IOException {
        XYChart chart = chart("Runs with a collision or a near miss against the period (95 % Wilson intervals)", axis,
                "runs (%)");
        int colour = 0;
        for (Map.Entry<String, List<SetSummary>> e : lines.entrySet()) {
            String suffix = lines.size() > 1 ? " (" + e.getKey() + ")" : "";
            List<SetSummary> sets = e.getValue().stream().filter(s -> s.measuredRuns() > 0).toList();
            interval(chart, "collided" + suffix, sets, axis, SetSummary::collisions95, colour, SOLID);
            interval(chart, "near miss" + suffix, sets, axis, SetSummary::nearMisses95, colour + 1, DASHES[1]);
            Double bound = PaperClaims.reactionRuleBoundMs(e.getValue());
            if (bound != null && bound > 0) {
                XYSeries line = chart.addSeries(String.format(Locale.ROOT,
                        "reaction rule's largest safe period %.1f ms", bound) + suffix, List.of(bound, bound), List.of(0.0, 100.0));
                line.setLineColor(Figures.colour(colour + 2));
                line.setMarker(SeriesMarkers.NONE);
                line.setLineStyle(new BasicStroke(2f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, DASHES[2], 0f));
            }
            colour += 3;
        }
        chart.getStyler().setYAxisMin(0.0).setYAxisMax(100.0);
        Figures.save(chart, dir, PERIOD_SAFETY);
    }

    /** A rate with its interval: the points joined by a line, each interval a segment of its own. */
    private static void interval(XYChart chart, String name, List<SetSummary> sets, Axis axis,
                                 Function<SetSummary, RateInterval> rate, int colour, float[] dash) {
        if (sets.isEmpty()) {
            return;
        }
        add(chart, name, sets, axis, s -> 100 * rate.apply(s).rate(), s -> null, colour, dash);
        for (SetSummary s : sets) {
            RateInterval r = rate.apply(s);
            double x = axis.x().apply(s);
            XYSeries segment = chart.addSeries(name + " interval at " + s.sweptPeriodMs() + " ms", List.of(x, x),
                    List.of(100 * r.lower(), 100 * r.upper()));
            segment.setLineColor(Figures.colour(colour));
            segment.setMarker(SeriesMarkers.NONE);
            segment.setLineStyle(new BasicStroke(1f));
            segment.setShowInLegend(false);
        }
    }

    private static Map<String, List<SetSummary>> lines(ExperimentSummary summary, Axis axis) {
        Map<String, List<SetSummary>> lines = new LinkedHashMap<>();
        for (SetSummary s : summary.sets()) {
            if (axis.x().apply(s) != null) {
                lines.computeIfAbsent(axis.line().apply(s), k -> new ArrayList<>()).add(s);
            }
        }
        lines.values().forEach(l -> l.sort(Comparator.comparingDouble(s -> axis.x().apply(s))));
        return lines;
    }

    private static XYChart chart(String title, Axis axis, String yTitle) {
        XYChart chart = new XYChartBuilder().width(WIDTH).height(HEIGHT).title(title).xAxisTitle(axis.title())
                .yAxisTitle(yTitle).build();
        Figures.style(chart.getStyler());
        chart.getStyler().setXAxisLogarithmic(axis.log());
        chart.getStyler().setLegendPosition(Styler.LegendPosition.OutsideE);
        chart.getStyler().setErrorBarsColorSeriesColor(true);
        chart.getStyler().setDecimalPattern("0.##");
        return chart;
    }

    private static void add(XYChart chart, String name, List<SetSummary> sets, Axis axis, Function<SetSummary, Double> y,
                            Function<SetSummary, Double> error, int colour, float[] dash) {
        List<Double> xs = new ArrayList<>();
        List<Double> ys = new ArrayList<>();
        List<Double> errors = new ArrayList<>();
        for (SetSummary s : sets) {
            Double v = y.apply(s);
            if (v != null && Double.isFinite(v)) {
                xs.add(axis.x().apply(s));
                ys.add(v);
                Double e = error.apply(s);
                errors.add(e == null ? 0.0 : e);
            }
        }
        if (xs.isEmpty()) {
            return;
        }
        boolean bars = sets.stream().map(error).anyMatch(Objects::nonNull);
        XYSeries series = bars ? chart.addSeries(name, xs, ys, errors) : chart.addSeries(name, xs, ys);
        series.setLineColor(Figures.colour(colour));
        series.setMarkerColor(Figures.colour(colour));
        series.setMarker(SeriesMarkers.CIRCLE);
        series.setLineStyle(dash == SOLID ? new BasicStroke(2f)
                : new BasicStroke(2f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, dash, 0f));
    }

    private static Double percent(Double share) {
        return share == null ? null : 100 * share;
    }

    private static Double sdOrZero(SampleStats s) {
        return s.mean() == null ? null : s.sd() == null ? 0.0 : s.sd();
    }

    private static String speed(Double speedMps) {
        return speedMps == null ? "default top speed" : PeriodSet.plainSpeed(speedMps) + " m/s";
    }
}
