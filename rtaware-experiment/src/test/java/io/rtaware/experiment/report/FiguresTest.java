package io.rtaware.experiment.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.output.Palette;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.Rectangle;
import java.awt.image.BufferedImage;
import java.util.LinkedHashMap;
import java.util.Map;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.junit.jupiter.api.Test;

/** The experiment's figures, checked on the pixels they draw. */
class FiguresTest {

    /** The case: a box plot of one run was an empty frame. */
    @Test
    void aSetOfOneOrTwoRunsShowsEachRunAsADotInItsColour() {
        Map<String, double[]> samples = new LinkedHashMap<>();
        samples.put("Set 1", new double[] {251.3});
        samples.put("Set 2", new double[] {240.0, 262.5});
        samples.put("Set 3", new double[] {});
        samples.put("Set 4", new double[] {230, 240, 250, 260, 270});
        XYChart chart = Figures.boxChart(samples, "Run time per set (completed runs)", "run time (s)");
        BufferedImage img = paint(chart);
        int set = 0;
        int dotsChecked = 0;
        for (Map.Entry<String, double[]> e : samples.entrySet()) {
            Color colour = Palette.colour(set++);
            for (double v : e.getValue()) {
                XYSeries dots = chart.getSeriesMap().get(e.getKey() + " (n=" + e.getValue().length + ")");
                double[] xs = dots.getXData();
                double[] ys = dots.getYData();
                boolean drawn = false;
                for (int i = 0; i < xs.length; i++) {
                    if (ys[i] == v) {
                        drawn |= nearest(img, chart.getScreenXFromChart(xs[i]), chart.getScreenYFromChart(ys[i]), colour) < 10;
                    }
                }
                assertTrue(drawn, e.getKey() + "'s run of " + v + " is drawn as a dot in " + colour);
                dotsChecked++;
            }
        }
        assertEquals(8, dotsChecked);
        assertFalse(chart.getSeriesMap().containsKey("Set 1 box"), "no box for one run");
        assertFalse(chart.getSeriesMap().containsKey("Set 2 box"), "nor for two");
        assertTrue(chart.getSeriesMap().containsKey("Set 4 box"), "a box from three runs on");
        assertLegendClearOf(chart);
    }

    @Test
    void aTitleTooWideForTheFigureIsShrunkToFitIt() {
        String title = "Paths driven, one colour per set: true (solid), believed by odometry (dashed), over the course"
                + " of the paper's room with its box and two pillars";
        XYChart fitted = new XYChartBuilder().width(1000).height(600).title(title).build();
        Figures.style(fitted.getStyler());
        fitted.addSeries("a", new double[] {0, 1}, new double[] {0, 1});
        XYChart unfitted = new XYChartBuilder().width(1000).height(600).title(title).build();
        Figures.style(unfitted.getStyler());
        unfitted.addSeries("a", new double[] {0, 1}, new double[] {0, 1});
        assertTrue(inkAtTheSidesOfTheTitle(paint(unfitted)) > 0, "the test's title is too wide at 18 pt");
        Figures.fitTitle(fitted);
        assertEquals(0, inkAtTheSidesOfTheTitle(paint(fitted)), "the fitted title stays inside the image");
    }

    /** Dark pixels in the outermost 3 columns of the title's band (the top 40 rows). */
    private static int inkAtTheSidesOfTheTitle(BufferedImage img) {
        int ink = 0;
        for (int y = 0; y < 40; y++) {
            for (int x : new int[] {0, 1, 2, img.getWidth() - 3, img.getWidth() - 2, img.getWidth() - 1}) {
                Color c = new Color(img.getRGB(x, y));
                ink += c.getRed() + c.getGreen() + c.getBlue() < 600 ? 1 : 0;
            }
        }
        return ink;
    }

    /**
     * Every data point of every series lies outside the legend's box, found on the painted
     * pixels: the legend's background in a colour nothing else has.
     *
     * @param chart a chart
     */
    static void assertLegendClearOf(XYChart chart) {
        Color mark = new Color(0xFF00FF);
        chart.getStyler().setLegendBackgroundColor(mark);
        BufferedImage img = paint(chart);
        Rectangle legend = null;
        for (int y = 0; y < img.getHeight(); y++) {
            for (int x = 0; x < img.getWidth(); x++) {
                if (img.getRGB(x, y) == mark.getRGB()) {
                    legend = legend == null ? new Rectangle(x, y, 1, 1) : legend.union(new Rectangle(x, y, 1, 1));
                }
            }
        }
        assertNotNull(legend, "the legend is drawn");
        for (XYSeries s : chart.getSeriesMap().values()) {
            double[] xs = s.getXData();
            double[] ys = s.getYData();
            for (int i = 0; i < xs.length; i++) {
                double x = chart.getScreenXFromChart(xs[i]);
                double y = chart.getScreenYFromChart(ys[i]);
                assertFalse(legend.contains(x, y), "the legend " + legend + " covers " + s.getName() + "'s point ("
                        + xs[i] + ", " + ys[i] + ") at " + x + "," + y);
            }
        }
    }

    private static BufferedImage paint(XYChart chart) {
        BufferedImage img = new BufferedImage(chart.getWidth(), chart.getHeight(), BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        chart.paint(g, chart.getWidth(), chart.getHeight());
        g.dispose();
        return img;
    }

    /** The smallest difference in RGB from {@code expected} among the 3 x 3 pixels around (x, y). */
    private static double nearest(BufferedImage img, double x, double y, Color expected) {
        double best = Double.MAX_VALUE;
        for (int dx = -1; dx <= 1; dx++) {
            for (int dy = -1; dy <= 1; dy++) {
                Color c = new Color(img.getRGB((int) Math.round(x) + dx, (int) Math.round(y) + dy));
                best = Math.min(best, Math.abs(c.getRed() - expected.getRed()) + Math.abs(c.getGreen() - expected.getGreen())
                        + Math.abs(c.getBlue() - expected.getBlue()));
            }
        }
        return best;
    }
}
