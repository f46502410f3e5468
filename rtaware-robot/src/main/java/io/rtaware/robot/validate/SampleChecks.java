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
 *   <li>a scan's declared minimum range is finite, &gt;= 0 and below its maximum; it has at least
 *       one beam, and no fewer than its own angles imply ({@link LaserScan#impliedBeams}, one beam
 *       of slack for drivers that count the end points differently);</li>
 *   <li>a reading is one of what {@link LaserScan} defines: below the minimum range (including
 *       {@code -Inf}: an obstacle at the minimum range), up to the declared maximum plus
 *       {@link SampleLimits#rangeTolerance()} of it, or {@code +Inf} (nothing hit). A finite
 *       reading beyond that tolerance, or NaN, says nothing: {@link #normalizeBeams} sets it
 *       to NaN and counts it, and the scan is kept while at least one beam is usable;</li>
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
     * Puts every reading into the form {@link LaserScan} defines, before {@link #scan}: a reading
     * below the minimum range (including {@code -Inf}, "closer than the sensor can measure",
     * REP 117) becomes the minimum range, an obstacle there; {@code +Inf} ("no return within
     * range") becomes the maximum range; NaN and a finite reading beyond the declared maximum
     * plus {@link SampleLimits#rangeTolerance()} of it say nothing (the
     * {@code sensor_msgs/msg/LaserScan} definition says such values are to be discarded): they are
     * set to NaN and counted. {@link #scan} then rejects a scan left without a usable beam.
     *
     * @param s a decoded scan; changed in place
     * @param limits the bounds
     * @return how many beams were dropped (set to NaN, or NaN already)
     */
    public static int normalizeBeams(LaserScan s, SampleLimits limits) {
        double ceiling = s.maxRangeM * (1 + limits.rangeTolerance());
        float min = (float) s.minRangeM;
        float max = (float) s.maxRangeM;
        float[] r = s.rangesM;
        int dropped = 0;
        for (int i = 0, n = s.count(); i < n; i++) {
            float v = r[i];
            if (v < min) {
                r[i] = min;
            } else if (v == Float.POSITIVE_INFINITY) {
                r[i] = max;
            } else if (!(v <= ceiling)) { // also true for NaN
                r[i] = Float.NaN;
                dropped++;
            }
        }
        return dropped;
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
     * @param s a scan with its geometry and timestamp, after {@link #normalizeBeams}
     * @param previousTimeS the previous accepted scan's timestamp, or NaN
     * @param limits the bounds
     * @return why the scan cannot be true, or null
     */
    public static String scan(LaserScan s, double previousTimeS, SampleLimits limits) {
        String bad = scanGeometry(s.minAngleRad, s.maxAngleRad, s.maxRangeM, limits);
        if (bad != null) {
            return bad;
        }
        if (!(s.minRangeM >= 0 && s.minRangeM < s.maxRangeM)) {
            return String.format(Locale.ROOT, "min range = %s m is outside [0, %s) m", s.minRangeM, s.maxRangeM);
        }
        int n = s.count();
        if (n == 0) {
            return "the scan has no beams";
        }
        if (s.impliedBeams > 0 && n < s.impliedBeams - 1) {
            return String.format(Locale.ROOT, "the scan has %d beams where its angles [%s, %s] rad imply %d", n,
                    s.minAngleRad, s.maxAngleRad, s.impliedBeams);
        }
        float[] r = s.rangesM;
        int usable = 0;
        for (int i = 0; i < n; i++) {
            if (!Float.isNaN(r[i])) {
                usable++;
            }
        }
        if (usable == 0) {
            return String.format(Locale.ROOT, "none of the %d beams is a reading within [%s, %s] m (or an infinity)",
                    n, s.minRangeM, s.maxRangeM);
        }
        return timestamp(s.serverTimeS, previousTimeS);
    }

    private static String finite(String field, double v) {
        return Double.isFinite(v) ? null : field + " = " + v;
    }
}
