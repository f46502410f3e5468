package io.rtaware.robot.validate;

import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.Odometry;
import java.util.Locale;

/**
 * The rules that decide whether a sample from the network can be true. Each check returns
 * {@code null} when the sample is plausible, or one line naming the first offending field and
 * its value (a new string, so only a rejection allocates). Stateless and thread-safe.
 *
 * <p>The rules:
 * <ul>
 *   <li>every number is finite (no NaN, no infinity);</li>
 *   <li>a pose lies within {@link SampleLimits#maxAbsCoordinateM()} of the origin and its |yaw|
 *       is at most {@link SampleLimits#maxAbsYawRad()};</li>
 *   <li>the planar speed is at most {@link SampleLimits#maxSpeedMps()}, the |turn rate| at most
 *       {@link SampleLimits#maxTurnRateRadPerSec()};</li>
 *   <li>a scan's angles satisfy -2 pi &lt;= min &lt;= max &lt;= 2 pi with max - min &lt;= 2 pi;
 *       its declared maximum range is positive and at most
 *       {@link SampleLimits#maxSensorRangeM()};</li>
 *   <li>every range reading is &gt;= 0 and at most the declared maximum plus
 *       {@link SampleLimits#rangeTolerance()} of it (one bad beam rejects the whole scan);</li>
 *   <li>a timestamp is &gt;= 0 and never earlier than the previous accepted sample's of the
 *       same device (equal is allowed: a server may repeat data).</li>
 * </ul>
 */
public final class SampleChecks {

    private SampleChecks() {
    }

    /**
     * @param xM x in metres
     * @param yM y in metres
     * @param yawRad heading in radians
     * @param limits the bounds
     * @return why the pose cannot be true, or null
     */
    public static String pose(double xM, double yM, double yawRad, SampleLimits limits) {
        String bad = finite("x", xM);
        bad = bad != null ? bad : finite("y", yM);
        bad = bad != null ? bad : finite("yaw", yawRad);
        if (bad != null) {
            return bad;
        }
        if (Math.abs(xM) > limits.maxAbsCoordinateM() || Math.abs(yM) > limits.maxAbsCoordinateM()) {
            return String.format(Locale.ROOT, "position (%s, %s) m is farther than %s m from the origin",
                    xM, yM, limits.maxAbsCoordinateM());
        }
        if (Math.abs(yawRad) > limits.maxAbsYawRad()) {
            return String.format(Locale.ROOT, "yaw = %s rad is beyond +-%s rad", yawRad, limits.maxAbsYawRad());
        }
        return null;
    }

    /**
     * @param vxMps forward speed
     * @param vyMps sideways speed
     * @param omegaRadPerSec turn rate
     * @param limits the bounds
     * @return why the velocity cannot be true, or null
     */
    public static String velocity(double vxMps, double vyMps, double omegaRadPerSec, SampleLimits limits) {
        String bad = finite("vx", vxMps);
        bad = bad != null ? bad : finite("vy", vyMps);
        bad = bad != null ? bad : finite("turn rate", omegaRadPerSec);
        if (bad != null) {
            return bad;
        }
        double speed = Math.hypot(vxMps, vyMps);
        if (speed > limits.maxSpeedMps()) {
            return String.format(Locale.ROOT, "speed = %s m/s is above %s m/s", speed, limits.maxSpeedMps());
        }
        if (Math.abs(omegaRadPerSec) > limits.maxTurnRateRadPerSec()) {
            return String.format(Locale.ROOT, "turn rate = %s rad/s is beyond +-%s rad/s", omegaRadPerSec,
                    limits.maxTurnRateRadPerSec());
        }
        return null;
    }

    /**
     * @param timeS the sample's timestamp in seconds
     * @param previousTimeS the previous accepted sample's timestamp of the same device, or
     *     {@link Double#NaN} for the first sample of a connection
     * @return why the timestamp cannot be true, or null
     */
    public static String timestamp(double timeS, double previousTimeS) {
        String bad = finite("timestamp", timeS);
        if (bad != null) {
            return bad;
        }
        if (timeS < 0) {
            return "timestamp = " + timeS + " s is negative";
        }
        if (timeS < previousTimeS) {
            return "timestamp = " + timeS + " s is earlier than the previous sample's " + previousTimeS + " s";
        }
        return null;
    }

    /**
     * Checks a range sensor's declared geometry (from its data or its configuration).
     *
     * @param minAngleRad bearing of the first beam
     * @param maxAngleRad bearing of the last beam
     * @param maxRangeM declared maximum range
     * @param limits the bounds
     * @return why the geometry cannot be true, or null
     */
    public static String scanGeometry(double minAngleRad, double maxAngleRad, double maxRangeM,
                                      SampleLimits limits) {
        String bad = finite("min angle", minAngleRad);
        bad = bad != null ? bad : finite("max angle", maxAngleRad);
        bad = bad != null ? bad : finite("max range", maxRangeM);
        if (bad != null) {
            return bad;
        }
        double turn = SampleLimits.FULL_TURN_RAD;
        if (minAngleRad < -turn || maxAngleRad > turn || minAngleRad > maxAngleRad
                || maxAngleRad - minAngleRad > turn + 1e-6) {
            return String.format(Locale.ROOT, "angles [%s, %s] rad are not a field of view within one turn",
                    minAngleRad, maxAngleRad);
        }
        if (!(maxRangeM > 0) || maxRangeM > limits.maxSensorRangeM()) {
            return String.format(Locale.ROOT, "max range = %s m is outside (0, %s] m", maxRangeM,
                    limits.maxSensorRangeM());
        }
        return null;
    }

    /**
     * @param o a position2d state with its timestamp
     * @param previousTimeS the previous accepted state's timestamp, or NaN
     * @param limits the bounds
     * @return why the state cannot be true, or null
     */
    public static String odometry(Odometry o, double previousTimeS, SampleLimits limits) {
        String bad = pose(o.xM, o.yM, o.yawRad, limits);
        bad = bad != null ? bad : velocity(o.vxMps, o.vyMps, o.omegaRadPerSec, limits);
        return bad != null ? bad : timestamp(o.serverTimeS, previousTimeS);
    }

    /**
     * @param s a scan with its geometry and timestamp
     * @param previousTimeS the previous accepted scan's timestamp, or NaN
     * @param limits the bounds
     * @return why the scan cannot be true, or null
     */
    public static String scan(LaserScan s, double previousTimeS, SampleLimits limits) {
        String bad = scanGeometry(s.minAngleRad, s.maxAngleRad, s.maxRangeM, limits);
        if (bad != null) {
            return bad;
        }
        double ceiling = s.maxRangeM * (1 + limits.rangeTolerance());
        float[] r = s.rangesM;
        for (int i = 0, n = s.count(); i < n; i++) {
            float v = r[i];
            if (!(v >= 0 && v <= ceiling)) { // also false for NaN
                return String.format(Locale.ROOT, "range[%d] = %s m is outside [0, %s] m", i, v, s.maxRangeM);
            }
        }
        return timestamp(s.serverTimeS, previousTimeS);
    }

    private static String finite(String field, double v) {
        return Double.isFinite(v) ? null : field + " = " + v;
    }
}
