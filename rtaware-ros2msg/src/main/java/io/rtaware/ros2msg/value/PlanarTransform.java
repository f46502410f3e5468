package io.rtaware.ros2msg.value;

import java.util.Objects;

/**
 * A transform between two frames in the plane: a translation and a rotation about z, as
 * {@code /tf} and {@code /tf_static} carry it (REP 105: e.g. {@code base_link} to {@code laser}).
 * Immutable.
 *
 * @param parent the parent frame, e.g. {@code base_link}
 * @param child the child frame, e.g. {@code laser}
 * @param xM translation x in metres
 * @param yM translation y in metres
 * @param yawRad rotation about z in radians
 */
public record PlanarTransform(String parent, String child, double xM, double yM, double yawRad) {

    /**
     * @param parent the parent frame, e.g. {@code base_link}
     * @param child the child frame, e.g. {@code laser}
     * @param xM translation x in metres
     * @param yM translation y in metres
     * @param yawRad rotation about z in radians
     * @throws NullPointerException if a frame is null
     * @throws IllegalArgumentException if a frame is empty or a number is not finite
     */
    public PlanarTransform {
        Objects.requireNonNull(parent, "parent");
        Objects.requireNonNull(child, "child");
        if (parent.isEmpty() || child.isEmpty()) {
            throw new IllegalArgumentException("frames must not be empty, got '" + parent + "' -> '" + child + "'");
        }
        if (!Double.isFinite(xM) || !Double.isFinite(yM) || !Double.isFinite(yawRad)) {
            throw new IllegalArgumentException("transform " + parent + " -> " + child + " must be finite, got x = " + xM
                    + ", y = " + yM + ", yaw = " + yawRad);
        }
    }
}
