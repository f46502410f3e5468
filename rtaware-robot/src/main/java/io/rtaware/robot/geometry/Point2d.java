package io.rtaware.robot.geometry;

/**
 * A point in the plane. Immutable.
 *
 * @param xM x in metres
 * @param yM y in metres
 */
public record Point2d(double xM, double yM) {

    /**
     * @param other another point
     * @return distance in metres
     */
    public double distanceTo(Point2d other) {
        return Math.hypot(other.xM - xM, other.yM - yM);
    }

    /**
     * @param xOtherM x of another point in metres
     * @param yOtherM y of another point in metres
     * @return distance in metres
     */
    public double distanceTo(double xOtherM, double yOtherM) {
        return Math.hypot(xOtherM - xM, yOtherM - yM);
    }
}
