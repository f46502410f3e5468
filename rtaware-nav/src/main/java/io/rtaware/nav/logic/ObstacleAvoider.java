package io.rtaware.nav.logic;

import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.MotionRequest;

/**
 * The obstacle avoider's decision, from one laser scan alone (it never reads the position).
 * The safety zone is the sector of beams within {@code halfAngleRad} of straight ahead, out to
 * {@code safetyRangeM}. When a valid reading falls inside it, the avoider requests control of
 * the motors, slows down to {@code slowSpeedMps} (or stops moving forward if the obstacle is
 * closer than {@code stopRangeM}) and turns at {@code turnRateRadPerSec} away from the nearer
 * side: an obstacle nearer on the left turns right. When both sides are equally near (within
 * 1 cm), it turns toward the side of the whole scan with the larger mean range. Otherwise it
 * requests nothing. Readings mean what {@link LaserScan} defines: one below the scan's minimum
 * range (0 and {@code -Inf} included) is an obstacle at the minimum range, so a sensor blinded
 * by something against it stops the robot; one at or beyond the maximum range hit nothing; NaN
 * is no reading and is ignored.
 *
 * <p>Immutable and thread-safe; allocates nothing.
 */
public final class ObstacleAvoider {

    private static final double TIE_M = 0.01;

    private final double safetyRangeM;
    private final double halfAngleRad;
    private final double stopRangeM;
    private final double slowSpeedMps;
    private final double turnRateRadPerSec;

    /**
     * @param safetyRangeM depth of the safety zone in metres
     * @param halfAngleRad half-width of the safety sector in radians
     * @param stopRangeM below this range the avoider only turns, in metres
     * @param slowSpeedMps forward speed while avoiding in m/s
     * @param turnRateRadPerSec turn rate while avoiding in rad/s
     * @throws IllegalArgumentException naming the bad value
     */
    public ObstacleAvoider(double safetyRangeM, double halfAngleRad, double stopRangeM,
                           double slowSpeedMps, double turnRateRadPerSec) {
        positive("safetyRangeM", safetyRangeM);
        positive("halfAngleRad", halfAngleRad);
        positive("turnRateRadPerSec", turnRateRadPerSec);
        if (!(stopRangeM >= 0 && stopRangeM <= safetyRangeM)) {
            throw new IllegalArgumentException("stopRangeM must be in 0..safetyRangeM, got " + stopRangeM);
        }
        if (!(slowSpeedMps >= 0) || Double.isInfinite(slowSpeedMps)) {
            throw new IllegalArgumentException("slowSpeedMps must be >= 0, got " + slowSpeedMps);
        }
        this.safetyRangeM = safetyRangeM;
        this.halfAngleRad = halfAngleRad;
        this.stopRangeM = stopRangeM;
        this.slowSpeedMps = slowSpeedMps;
        this.turnRateRadPerSec = turnRateRadPerSec;
    }

    private static void positive(String name, double v) {
        if (!(v > 0) || Double.isInfinite(v)) {
            throw new IllegalArgumentException(name + " must be > 0, got " + v);
        }
    }

    /**
     * Decides on one scan.
     *
     * @param scan the scan
     * @param out receives the request: active with a speed and turn rate, or released
     * @return true if the avoider requests control
     */
    public boolean decide(LaserScan scan, MotionRequest out) {
        int n = scan.count();
        double maxRange = scan.maxRangeM > 0 ? scan.maxRangeM : Double.MAX_VALUE;
        double nearestLeft = Double.MAX_VALUE;
        double nearestRight = Double.MAX_VALUE;
        double sumLeft = 0;
        double sumRight = 0;
        int beamsLeft = 0;
        int beamsRight = 0;
        for (int i = 0; i < n; i++) {
            double bearing = scan.bearingRad(i);
            double r = scan.obstacleRangeM(i);
            boolean valid = !Double.isNaN(r);
            double seen = !valid ? 0 : Math.min(r, maxRange);
            if (bearing >= 0) {
                sumLeft += seen;
                beamsLeft++;
            } else {
                sumRight += seen;
                beamsRight++;
            }
            if (!valid || r >= maxRange || r >= safetyRangeM || Math.abs(bearing) > halfAngleRad) {
                continue;
            }
            if (bearing >= 0) {
                nearestLeft = Math.min(nearestLeft, r);
            } else {
                nearestRight = Math.min(nearestRight, r);
            }
        }
        double nearest = Math.min(nearestLeft, nearestRight);
        if (nearest == Double.MAX_VALUE) {
            out.release();
            return false;
        }
        boolean turnRight;
        if (Math.abs(nearestLeft - nearestRight) <= TIE_M) {
            double meanLeft = beamsLeft == 0 ? 0 : sumLeft / beamsLeft;
            double meanRight = beamsRight == 0 ? 0 : sumRight / beamsRight;
            turnRight = meanRight > meanLeft;
        } else {
            turnRight = nearestLeft < nearestRight;
        }
        double speed = nearest < stopRangeM ? 0.0 : slowSpeedMps;
        out.request(speed, turnRight ? -turnRateRadPerSec : turnRateRadPerSec);
        return true;
    }
}
