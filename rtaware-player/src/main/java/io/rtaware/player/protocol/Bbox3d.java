package io.rtaware.player.protocol;

import java.util.Locale;

/**
 * A bounding box ({@code player_bbox3d_t}, 24 bytes: sw, sl, sh). Immutable and thread-safe.
 *
 * @param widthM width in metres
 * @param lengthM length in metres
 * @param heightM height in metres
 */
public record Bbox3d(double widthM, double lengthM, double heightM) {

    /** @return what a person reads: width x length x height, e.g. {@code 0.30 x 0.30 x 0.20 m} */
    @Override
    public String toString() {
        return String.format(Locale.ROOT, "%.2f x %.2f x %.2f m", widthM, lengthM, heightM);
    }
}
