package io.rtaware.core.output;

import java.awt.Font;
import java.awt.image.BufferedImage;
import java.util.function.Consumer;
import java.util.function.Supplier;

/**
 * Titles that fit the figure they are drawn on. A chart library may centre a title over the
 * plot rather than the image (XChart does, and a legend beside the plot moves the plot's centre),
 * so whether a title fits is measured on the figure as painted: the title keeps its font if the
 * margins of its band stay empty, and is drawn smaller until they do, down to
 * {@link #SMALLEST_PT}. Stateless.
 */
public final class FigureText {

    /** The smallest size a title shrinks to, points. */
    public static final int SMALLEST_PT = 9;

    private FigureText() {
    }

    /**
     * Sets the title's font: {@code font} if the title fits, else the same font at the largest
     * size (not below {@link #SMALLEST_PT}) at which no pixel of the title's band (the top
     * {@code marginPx} plus twice the font's size rows) within {@code marginPx} of either side
     * differs from the figure's top left pixel (its background).
     *
     * @param font the title's font
     * @param setFont sets the title's font on the figure
     * @param paint paints the whole figure as it is set
     * @param marginPx the figure's empty margin left and right of its title, pixels (at least 1)
     * @return the font set
     */
    public static Font fitTitle(Font font, Consumer<Font> setFont, Supplier<BufferedImage> paint, int marginPx) {
        Font f = font;
        setFont.accept(f);
        while (f.getSize() > SMALLEST_PT && !marginsEmpty(paint.get(), marginPx, marginPx + 2 * f.getSize())) {
            f = f.deriveFont((float) (f.getSize() - 1));
            setFont.accept(f);
        }
        return f;
    }

    private static boolean marginsEmpty(BufferedImage img, int marginPx, int bandPx) {
        int background = img.getRGB(0, 0);
        int rows = Math.min(bandPx, img.getHeight());
        int margin = Math.min(marginPx, img.getWidth() / 2);
        for (int y = 0; y < rows; y++) {
            for (int i = 0; i < margin; i++) {
                if (img.getRGB(i, y) != background || img.getRGB(img.getWidth() - 1 - i, y) != background) {
                    return false;
                }
            }
        }
        return true;
    }
}
