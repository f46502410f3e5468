package io.rtaware.player.protocol;

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
}
