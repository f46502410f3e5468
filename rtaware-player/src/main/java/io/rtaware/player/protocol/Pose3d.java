package io.rtaware.player.protocol;

import java.util.Locale;

/**
 * A 3D pose ({@code player_pose3d_t}, 48 bytes). Immutable and thread-safe.
 *
 * @param xM x in metres
 * @param yM y in metres
 * @param zM z in metres
 * @param rollRad roll in radians
 * @param pitchRad pitch in radians
 * @param yawRad yaw in radians
 */
public record Pose3d(double xM, double yM, double zM, double rollRad, double pitchRad, double yawRad) {

    /**
     * @return what a person reads, e.g. {@code at (0.100, 0.000, 0.200) m, yaw 90.0 deg}; roll and
     *     pitch only when they are not zero
     */
    @Override
    public String toString() {
        String tilt = rollRad == 0 && pitchRad == 0 ? ""
                : String.format(Locale.ROOT, ", roll %.1f deg, pitch %.1f deg", Math.toDegrees(rollRad), Math.toDegrees(pitchRad));
        return String.format(Locale.ROOT, "at (%.3f, %.3f, %.3f) m, yaw %.1f deg%s", xM, yM, zM, Math.toDegrees(yawRad), tilt);
    }
}
