package io.rtaware.core.output;

import java.awt.Color;
import java.util.List;

/**
 * The one set of colours every figure gives its tasks, sets and executors, in order: the first
 * eight colours of the Tableau 10 qualitative palette (the classic {@code category10}: blue,
 * orange, green, red, purple, brown, pink, grey). Any two of them differ by at least 27 in CIE
 * L*a*b* (ΔE*76; about 2.3 is a just-noticeable difference), and each stands out from a white
 * background by a WCAG contrast ratio of at least 2.5, so a thin line in any of them is visible.
 * A ninth series cycles back to the first colour. Stateless.
 */
public final class Palette {

    /** The colours in the order series receive them. */
    public static final List<Color> COLOURS = List.of(new Color(0x1F77B4), new Color(0xFF7F0E), new Color(0x2CA02C),
            new Color(0xD62728), new Color(0x9467BD), new Color(0x8C564B), new Color(0xE377C2), new Color(0x7F7F7F));

    private Palette() {
    }

    /**
     * @param index a zero-based series index (a task, a set, an executor)
     * @return its colour; indexes from {@link #COLOURS}'s size on cycle
     */
    public static Color colour(int index) {
        return COLOURS.get(Math.floorMod(index, COLOURS.size()));
    }
}
