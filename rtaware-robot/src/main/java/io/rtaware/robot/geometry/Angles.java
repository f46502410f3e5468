package io.rtaware.robot.geometry;

/** Angle arithmetic in radians. */
public final class Angles {

    private Angles() {
    }

    /**
     * @param rad any angle
     * @return the same direction in [-pi, pi)
     */
    public static double normalize(double rad) {
        double a = rad % (2 * Math.PI);
        if (a >= Math.PI) {
            a -= 2 * Math.PI;
        } else if (a < -Math.PI) {
            a += 2 * Math.PI;
        }
        return a;
    }
}
