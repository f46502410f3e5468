package io.rtaware.core.output;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import org.junit.jupiter.api.Test;

/** The figures' colours, checked as a reader sees them: apart from each other and from the white page. */
class PaletteTest {

    @Test
    void anyTwoOfTheEightColoursAreClearlyDistinct() {
        assertEquals(8, Palette.COLOURS.size(), "one colour for each of up to eight tasks");
        for (int i = 0; i < Palette.COLOURS.size(); i++) {
            for (int j = i + 1; j < Palette.COLOURS.size(); j++) {
                double deltaE = deltaE76(Palette.colour(i), Palette.colour(j));
                assertTrue(deltaE >= 25, "colours " + i + " and " + j + " differ by only " + deltaE + " in L*a*b*");
            }
        }
    }

    @Test
    void eachColourStandsOutFromWhite() {
        for (Color c : Palette.COLOURS) {
            double ratio = (1.05) / (relativeLuminance(c) + 0.05);
            assertTrue(ratio >= 2.5, c + " on white has a contrast ratio of only " + ratio);
        }
    }

    @Test
    void aNinthSeriesCyclesBackToTheFirstColour() {
        assertEquals(Palette.colour(0), Palette.colour(8));
    }

    /** CIE 1976 colour difference of two sRGB colours (D65 white). */
    static double deltaE76(Color a, Color b) {
        double[] p = lab(a);
        double[] q = lab(b);
        return Math.sqrt(Math.pow(p[0] - q[0], 2) + Math.pow(p[1] - q[1], 2) + Math.pow(p[2] - q[2], 2));
    }

    private static double[] lab(Color c) {
        double r = linear(c.getRed());
        double g = linear(c.getGreen());
        double b = linear(c.getBlue());
        double x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047;
        double y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
        double z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883;
        return new double[] {116 * f(y) - 16, 500 * (f(x) - f(y)), 200 * (f(y) - f(z))};
    }

    private static double f(double t) {
        return t > 216.0 / 24389 ? Math.cbrt(t) : (24389.0 / 27 * t + 16) / 116;
    }

    private static double linear(int channel) {
        double c = channel / 255.0;
        return c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4);
    }

    /** WCAG 2 relative luminance. */
    static double relativeLuminance(Color c) {
        return 0.2126 * linear(c.getRed()) + 0.7152 * linear(c.getGreen()) + 0.0722 * linear(c.getBlue());
    }
}
