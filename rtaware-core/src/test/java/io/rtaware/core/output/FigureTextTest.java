package io.rtaware.core.output;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;

/** A title centred off the image's centre, as a chart centres it over a plot with a legend beside it. */
class FigureTextTest {

    private static final String TITLE = "Release lateness against task count (period 10 ms, work 0 ms, quiet machine)";

    /** Paints a 500 px wide figure whose title is centred at x = 200, as the font set says. */
    private static BufferedImage figure(String title, Font font) {
        BufferedImage img = new BufferedImage(500, 100, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, 500, 100);
        g.setColor(Color.BLACK);
        g.setFont(font);
        int width = g.getFontMetrics().stringWidth(title);
        g.drawString(title, 200 - width / 2, 10 + font.getSize());
        g.dispose();
        return img;
    }

    @Test
    void aTitleThatRunsOffTheFigureIsShrunkUntilItsMarginsAreEmpty() {
        AtomicReference<Font> set = new AtomicReference<>();
        Font big = new Font(Font.SANS_SERIF, Font.BOLD, 18);
        Font fitted = FigureText.fitTitle(big, set::set, () -> figure(TITLE, set.get()), 10);
        assertEquals(fitted, set.get(), "the font returned is the font set");
        assertTrue(fitted.getSize() < 18, "shrunk: " + fitted.getSize());
        BufferedImage img = figure(TITLE, fitted);
        for (int y = 0; y < img.getHeight(); y++) {
            for (int x = 0; x < 10; x++) {
                assertEquals(Color.WHITE.getRGB(), img.getRGB(x, y), "the left margin is empty at " + x + "," + y);
            }
        }
        Font larger = fitted.deriveFont((float) fitted.getSize() + 1);
        BufferedImage tooBig = figure(TITLE, larger);
        boolean ink = false;
        for (int y = 0; y < tooBig.getHeight(); y++) {
            for (int x = 0; x < 10; x++) {
                ink |= tooBig.getRGB(x, y) != Color.WHITE.getRGB();
            }
        }
        assertTrue(ink, "one point larger would not fit: the largest fitting size is kept");
    }

    @Test
    void aTitleThatFitsKeepsItsFont() {
        AtomicReference<Font> set = new AtomicReference<>();
        Font big = new Font(Font.SANS_SERIF, Font.BOLD, 18);
        assertEquals(big, FigureText.fitTitle(big, set::set, () -> figure("Misses per task", set.get()), 10));
        assertEquals(big, set.get());
    }
}
