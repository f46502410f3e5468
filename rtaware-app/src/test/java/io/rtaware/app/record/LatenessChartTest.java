package io.rtaware.app.record;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import io.rtaware.core.output.Palette;
import java.awt.Graphics2D;
import java.awt.Color;
import java.awt.Rectangle;
import java.awt.image.BufferedImage;
import java.util.LinkedHashMap;
import java.util.Map;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYSeries;
import org.junit.jupiter.api.Test;

/**
 * {@code inspect --plot}'s chart, laid out as it is drawn: the legend covers no point of any task
 * (the issue saw it cover the first spike, which comes at the start of a run), and each task has
 * its own colour of the one palette (the issue saw planner and mediator in near-identical yellows).
 */
class LatenessChartTest {

    private static final Color LEGEND_MARK = new Color(0xFF00FF);

    @Test
    void theLegendCoversNoPointAndEachTaskHasItsPaletteColour() throws Exception {
        Map<String, InspectCommand.TaskTiming> tasks = new LinkedHashMap<>();
        String[] names = {"player", "waypoint", "obstacle", "occupancy", "planner", "mediator"};
        for (int t = 0; t < names.length; t++) {
            InspectCommand.TaskTiming timing = new InspectCommand.TaskTiming();
            for (int i = 0; i <= 100; i++) {
                timing.timeS.add(i * 0.5);
                // a spike at the start of the run, as the first cycles of a JVM have
                timing.latenessMs.add(i < 3 ? 40.0 - t : 0.5 + 0.1 * t);
            }
            tasks.put(names[t], timing);
        }
        XYChart chart = InspectCommand.latenessChart(tasks);
        // The legend's box, found on the painted pixels: its background in a colour nothing else has.
        chart.getStyler().setLegendBackgroundColor(LEGEND_MARK);
        BufferedImage img = new BufferedImage(chart.getWidth(), chart.getHeight(), BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        chart.paint(g, chart.getWidth(), chart.getHeight());
        g.dispose();
        Rectangle legend = null;
        for (int y = 0; y < img.getHeight(); y++) {
            for (int x = 0; x < img.getWidth(); x++) {
                if (img.getRGB(x, y) == LEGEND_MARK.getRGB()) {
                    legend = legend == null ? new Rectangle(x, y, 1, 1) : legend.union(new Rectangle(x, y, 1, 1));
                }
            }
        }
        assertNotNull(legend, "the legend is drawn");
        int t = 0;
        for (XYSeries s : chart.getSeriesMap().values()) {
            assertEquals(Palette.colour(t++), s.getLineColor(), s.getName() + "'s colour");
            double[] xs = s.getXData();
            double[] ys = s.getYData();
            for (int i = 0; i < xs.length; i++) {
                double x = chart.getScreenXFromChart(xs[i]);
                double y = chart.getScreenYFromChart(ys[i]);
                assertFalse(legend.contains(x, y), "the legend " + legend + " covers " + s.getName() + " at ("
                        + xs[i] + " s, " + ys[i] + " ms)");
            }
        }
    }
}
