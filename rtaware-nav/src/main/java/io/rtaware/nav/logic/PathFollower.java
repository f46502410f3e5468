package io.rtaware.nav.logic;

import io.rtaware.robot.geometry.Angles;
import io.rtaware.robot.msg.MotionRequest;

/**
 * Pure pursuit along a polyline within a top speed and a turn-rate limit. The target is the
 * first path point at least {@code lookaheadM} from the robot after the path point nearest the
 * robot (the last point if none is that far). When the heading error to the target exceeds
 * {@code turnInPlaceRad} the robot turns in place toward it; otherwise it drives the arc
 * through the target ({@code curvature = 2 sin(alpha) / distance}) at the top speed, slowed so
 * that the turn rate stays within its limit.
 *
 * <p>Immutable and thread-safe; allocates nothing.
 */
public final class PathFollower {

    private static final double TURN_GAIN_PER_SEC = 2.0;

    private final double topSpeedMps;
    private final double maxOmegaRadPerSec;
    private final double lookaheadM;
    private final double turnInPlaceRad;

    /**
     * @param topSpeedMps top forward speed in m/s
     * @param maxOmegaRadPerSec turn-rate limit in rad/s
     * @param lookaheadM lookahead distance in metres
     * @param turnInPlaceRad heading error above which the robot turns in place, in radians
     * @throws IllegalArgumentException naming the bad value
     */
    public PathFollower(double topSpeedMps, double maxOmegaRadPerSec, double lookaheadM, double turnInPlaceRad) {
        positive("topSpeedMps", topSpeedMps);
        positive("maxOmegaRadPerSec", maxOmegaRadPerSec);
        positive("lookaheadM", lookaheadM);
        if (!(turnInPlaceRad > 0 && turnInPlaceRad <= Math.PI)) {
            throw new IllegalArgumentException("turnInPlaceRad must be in (0, pi], got " + turnInPlaceRad);
        }
        this.topSpeedMps = topSpeedMps;
        this.maxOmegaRadPerSec = maxOmegaRadPerSec;
        this.lookaheadM = lookaheadM;
        this.turnInPlaceRad = turnInPlaceRad;
    }

    private static void positive(String name, double v) {
        if (!(v > 0) || Double.isInfinite(v)) {
            throw new IllegalArgumentException(name + " must be > 0, got " + v);
        }
    }

    /**
     * Follows a path.
     *
     * @param xM robot x in metres
     * @param yM robot y in metres
     * @param yawRad robot heading in radians
     * @param pathXM x of the path points in metres
     * @param pathYM y of the path points in metres
     * @param count number of path points, at least 1
     * @param out receives an active request
     */
    public void follow(double xM, double yM, double yawRad, double[] pathXM, double[] pathYM, int count,
                       MotionRequest out) {
        if (count < 1) {
            throw new IllegalArgumentException("path has no points");
        }
        int nearest = 0;
        double best = Double.MAX_VALUE;
        for (int i = 0; i < count; i++) {
            double d = sq(pathXM[i] - xM) + sq(pathYM[i] - yM);
            if (d < best) {
                best = d;
                nearest = i;
            }
        }
        int target = count - 1;
        double l2 = lookaheadM * lookaheadM;
        for (int i = nearest; i < count; i++) {
            if (sq(pathXM[i] - xM) + sq(pathYM[i] - yM) >= l2) {
                target = i;
                break;
            }
        }
        driveTo(xM, yM, yawRad, pathXM[target], pathYM[target], out);
    }

    /**
     * Heads straight for a point (pure pursuit on a one-point path).
     *
     * @param xM robot x in metres
     * @param yM robot y in metres
     * @param yawRad robot heading in radians
     * @param targetXM target x in metres
     * @param targetYM target y in metres
     * @param out receives an active request
     */
    public void driveTo(double xM, double yM, double yawRad, double targetXM, double targetYM, MotionRequest out) {
        double dx = targetXM - xM;
        double dy = targetYM - yM;
        double d2 = dx * dx + dy * dy;
        if (d2 < 1e-12) {
            out.request(0, 0);
            return;
        }
        double alpha = Angles.normalize(Math.atan2(dy, dx) - yawRad);
        if (Math.abs(alpha) > turnInPlaceRad) {
            out.request(0, clamp(TURN_GAIN_PER_SEC * alpha, maxOmegaRadPerSec));
            return;
        }
        double curvature = 2 * Math.sin(alpha) / Math.sqrt(d2);
        double v = topSpeedMps;
        double omega = v * curvature;
        if (Math.abs(omega) > maxOmegaRadPerSec) {
            v = maxOmegaRadPerSec / Math.abs(curvature);
            omega = Math.copySign(maxOmegaRadPerSec, curvature);
        }
        out.request(v, omega);
    }

    private static double clamp(double v, double limit) {
        return Math.max(-limit, Math.min(limit, v));
    }

    private static double sq(double v) {
        return v * v;
    }
}
