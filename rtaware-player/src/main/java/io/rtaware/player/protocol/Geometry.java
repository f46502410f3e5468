package io.rtaware.player.protocol;

/**
 * Reply to position2d or laser REQ GET_GEOM: the device's pose on the robot and its size
 * (72 bytes). Immutable and thread-safe.
 *
 * @param pose pose of the device relative to the robot
 * @param size the device's extent
 */
public record Geometry(Pose3d pose, Bbox3d size) {

    /** @return what a person reads, e.g. {@code at (0.100, 0.000, 0.200) m, yaw 0.0 deg; size 0.30 x 0.30 x 0.20 m} */
    @Override
    public String toString() {
        return pose + "; size " + size;
    }
}
