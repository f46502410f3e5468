package io.rtaware.nav.testing;

import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.Odometry;

/**
 * A tiny kinematic world for closed-loop tests: axis-aligned walls and boxes as segments, a
 * unicycle robot, a URG-like laser by ray casting (683 beams over 240 degrees, 5.6 m), and a
 * collision check on the robot's radius.
 */
public final class SimRoom {

    /** URG beam count. */
    public static final int BEAMS = 683;
    /** URG half field of view in radians. */
    public static final double HALF_FOV_RAD = Math.toRadians(120);
    /** URG maximum range in metres. */
    public static final double MAX_RANGE_M = 5.6;

    private final double[] segs = new double[64 * 4];
    private int segCount;
    private final double radiusM;
    /** robot x in metres. */
    public double xM;
    /** robot y in metres. */
    public double yM;
    /** robot heading in radians. */
    public double yawRad;
    private boolean colliding;
    /** number of times the robot started touching an obstacle. */
    public int collisions;

    /**
     * @param radiusM robot radius in metres
     */
    public SimRoom(double radiusM) {
        this.radiusM = radiusM;
    }

    /**
     * Adds an axis-aligned rectangle's four edges.
     *
     * @param x0 min x
     * @param y0 min y
     * @param x1 max x
     * @param y1 max y
     * @return this
     */
    public SimRoom rect(double x0, double y0, double x1, double y1) {
        seg(x0, y0, x1, y0);
        seg(x1, y0, x1, y1);
        seg(x1, y1, x0, y1);
        seg(x0, y1, x0, y0);
        return this;
    }

    private void seg(double ax, double ay, double bx, double by) {
        int i = segCount++ * 4;
        segs[i] = ax;
        segs[i + 1] = ay;
        segs[i + 2] = bx;
        segs[i + 3] = by;
    }

    /** @param scan receives a scan from the current pose */
    public void scan(LaserScan scan) {
        scan.setCount(BEAMS);
        scan.minAngleRad = -HALF_FOV_RAD;
        scan.maxAngleRad = HALF_FOV_RAD;
        scan.maxRangeM = MAX_RANGE_M;
        for (int b = 0; b < BEAMS; b++) {
            double a = yawRad + scan.bearingRad(b);
            scan.rangesM[b] = (float) cast(xM, yM, Math.cos(a), Math.sin(a));
        }
    }

    /** @param odom receives the current pose (odometry frame = world frame) */
    public void odometry(Odometry odom) {
        odom.xM = xM;
        odom.yM = yM;
        odom.yawRad = yawRad;
    }

    /**
     * Moves the robot as a unicycle for a time step; counts a collision when it starts to
     * overlap an obstacle, and does not move into one.
     *
     * @param vMps forward speed
     * @param omegaRadPerSec turn rate
     * @param dtS step in seconds
     */
    public void step(double vMps, double omegaRadPerSec, double dtS) {
        double nx = xM + vMps * Math.cos(yawRad) * dtS;
        double ny = yM + vMps * Math.sin(yawRad) * dtS;
        yawRad += omegaRadPerSec * dtS;
        boolean touching = clearance(nx, ny) < radiusM;
        if (touching && !colliding) {
            collisions++;
        }
        colliding = touching;
        if (!touching) {
            xM = nx;
            yM = ny;
        }
    }

    /**
     * @param x point x
     * @param y point y
     * @return distance from the point to the nearest segment
     */
    public double clearance(double x, double y) {
        double best = Double.MAX_VALUE;
        for (int s = 0; s < segCount; s++) {
            int i = s * 4;
            double ax = segs[i];
            double ay = segs[i + 1];
            double dx = segs[i + 2] - ax;
            double dy = segs[i + 3] - ay;
            double t = ((x - ax) * dx + (y - ay) * dy) / (dx * dx + dy * dy);
            t = Math.max(0, Math.min(1, t));
            best = Math.min(best, Math.hypot(ax + t * dx - x, ay + t * dy - y));
        }
        return best;
    }

    private double cast(double ox, double oy, double dx, double dy) {
        double best = MAX_RANGE_M;
        for (int s = 0; s < segCount; s++) {
            int i = s * 4;
            double ax = segs[i];
            double ay = segs[i + 1];
            double ex = segs[i + 2] - ax;
            double ey = segs[i + 3] - ay;
            double den = dx * ey - dy * ex;
            if (Math.abs(den) < 1e-12) {
                continue;
            }
            double t = ((ax - ox) * ey - (ay - oy) * ex) / den;
            double u = ((ax - ox) * dy - (ay - oy) * dx) / den;
            if (t > 0 && u >= 0 && u <= 1 && t < best) {
                best = t;
            }
        }
        return best;
    }
}
