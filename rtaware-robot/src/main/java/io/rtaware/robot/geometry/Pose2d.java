package io.rtaware.robot.geometry;

/**
 * A position and heading in the plane. Immutable.
 *
 * @param xM x in metres
 * @param yM y in metres
 * @param yawRad heading in radians, counter-clockwise from +x
 */
public record Pose2d(double xM, double yM, double yawRad) {

    /** The origin, heading +x. */
    public static final Pose2d ORIGIN = new Pose2d(0, 0, 0);

    /** @return the position part */
    public Point2d position() {
        return new Point2d(xM, yM);
    }

    /**
     * @param other another pose
     * @return the Euclidean distance between the two positions in metres
     */
    public double distanceTo(Pose2d other) {
        return Math.hypot(other.xM - xM, other.yM - yM);
    }

    /**
     * @param other another pose
     * @return {@code other} expressed in this pose's frame
     */
    public Pose2d relativeTo(Pose2d other) {
        double dx = xM - other.xM;
        double dy = yM - other.yM;
        double c = Math.cos(-other.yawRad);
        double s = Math.sin(-other.yawRad);
        return new Pose2d(dx * c - dy * s, dx * s + dy * c, Angles.normalize(yawRad - other.yawRad));
    }

    /**
     * @param local a pose in this pose's frame
     * @return the same pose in the parent frame
     */
    public Pose2d transformBy(Pose2d local) {
        double c = Math.cos(yawRad);
        double s = Math.sin(yawRad);
        return new Pose2d(xM + local.xM * c - local.yM * s, yM + local.xM * s + local.yM * c,
                Angles.normalize(yawRad + local.yawRad));
    }

    /**
     * @param to the other end
     * @param t fraction from 0 (this) to 1 ({@code to})
     * @return the pose between, heading interpolated along the shorter arc
     */
    public Pose2d interpolate(Pose2d to, double t) {
        return new Pose2d(xM + (to.xM - xM) * t, yM + (to.yM - yM) * t,
                Angles.normalize(yawRad + Angles.normalize(to.yawRad - yawRad) * t));
    }
}
