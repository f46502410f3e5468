package io.rtaware.robot.validate;

/**
 * The bounds beyond which a value from the network cannot be true for a ground robot. They are
 * deliberately loose: they catch corruption (NaN, infinities, garbage bits, a wrong unit by
 * orders of magnitude), not a robot that is merely fast. Immutable and thread-safe.
 *
 * @param maxAbsCoordinateM largest |x| or |y| of a pose in metres
 * @param maxAbsYawRad largest |yaw| in radians (odometry of some drivers is not normalized, so
 *     this is a garbage guard, not 2 pi)
 * @param maxSpeedMps largest planar speed, hypot(vx, vy), in m/s
 * @param maxTurnRateRadPerSec largest |turn rate| in rad/s
 * @param maxSensorRangeM largest maximum range a range sensor may declare, in metres
 * @param rangeTolerance fraction of the declared maximum range a reading may exceed it by
 *     (float rounding of drivers that report "nothing hit" as the maximum)
 */
public record SampleLimits(double maxAbsCoordinateM, double maxAbsYawRad, double maxSpeedMps,
                           double maxTurnRateRadPerSec, double maxSensorRangeM, double rangeTolerance) {

    /** The largest field of view a planar scan may cover, one full turn, in radians. */
    public static final double FULL_TURN_RAD = 2 * Math.PI;

    /**
      * @param maxAbsCoordinateM largest |x| or |y| of a pose in metres
      * @param maxAbsYawRad largest |yaw| in radians (odometry of some drivers is not normalized, so this is a
      *     garbage guard, not 2 pi)
      * @param maxSpeedMps largest planar speed, hypot(vx, vy), in m/s
      * @param maxTurnRateRadPerSec largest |turn rate| in rad/s
      * @param maxSensorRangeM largest maximum range a range sensor may declare, in metres
      * @param rangeTolerance fraction of the declared maximum range a reading may exceed it by (float rounding
      *     of drivers that report "nothing hit" as the maximum)
     * @throws IllegalArgumentException if a bound is not positive and finite, or the tolerance
     *     is negative
      */
    public SampleLimits {
        for (double v : new double[] {maxAbsCoordinateM, maxAbsYawRad, maxSpeedMps, maxTurnRateRadPerSec,
                maxSensorRangeM}) {
            if (!(v > 0) || Double.isInfinite(v)) {
                throw new IllegalArgumentException("sample limits must be positive and finite, got " + v);
            }
        }
        if (!(rangeTolerance >= 0) || Double.isInfinite(rangeTolerance)) {
            throw new IllegalArgumentException("range tolerance must be >= 0 and finite, got " + rangeTolerance);
        }
    }

    /**
     * The defaults: poses within 100 km of the origin, |yaw| up to 1000 rad, speeds up to
     * 10 m/s, turn rates up to 20 rad/s, sensors of at most 1 km range, readings up to 1 %
     * beyond the declared maximum.
     *
     * @return the default limits
     */
    public static SampleLimits defaults() {
        return new SampleLimits(100_000.0, 1000.0, 10.0, 20.0, 1000.0, 0.01);
    }
}
