package io.rtaware.player.protocol;

/**
 * A bounding box ({@code player_bbox3d_t}, 24 bytes: sw, sl, sh). Immutable and thread-safe.
 *
 * @param widthM width in metres
 * @param lengthM length in metres
 * @param heightM height in metres
 */
public record Bbox3d(double widthM, double lengthM, double heightM) {
}
