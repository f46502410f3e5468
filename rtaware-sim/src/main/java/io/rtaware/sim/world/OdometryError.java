package io.rtaware.sim.world;

/**
 * How the robot's own odometry drifts from the truth, as dead reckoning from wheel encoders
 * does. Each run draws systematic errors once (uniformly in {@code [-e, +e]}, as Stage's
 * {@code position} model draws its {@code odom_error} per run) and adds zero-mean noise to
 * every increment, growing with the square root of the distance or angle travelled (a random
 * walk, so its statistics do not depend on the simulator's step). Immutable and validated.
 *
 * <p>Sources: Stage's {@code position} model ({@code localization "odom"}, {@code odom_error
 * [0.03 0.03 0.00 0.05]}: fractional errors of x, y, z and heading, drawn once per run); the
 * Koala 2.5 manual (wheel 82.5 mm unloaded, 80.5 mm with a 3 kg payload: a 2.4 % distance
 * scale error unless recalibrated); the skid-steer odometry literature (Mandow et al., IROS
 * 2007, "Experimental kinematics for wheeled skid-steer mobile robots"; Martinez et al.,
 * 2005): a six-wheeled skid-steer base turns by slipping, so its effective track width, and
 * with it the rotation measured by the encoders, is off by several to tens of percent
 * depending on the floor, and it errs far more in rotation than in distance.
 *
 * @param distanceScaleError bound of the per-run distance scale error, a fraction (0.03 = 3 %)
 * @param rotationScaleError bound of the per-run rotation scale error, a fraction
 * @param headingDriftRadPerM bound of the per-run heading drift per metre driven straight
 *     (unequal sides of a skid-steer base), radians per metre
 * @param distanceNoiseMPerSqrtM noise of the distance increments: standard deviation after
 *     one metre, metres per square-root metre
 * @param rotationNoiseRadPerSqrtRad noise of the rotation increments: standard deviation
 *     after one radian turned, radians per square-root radian
 */
public record OdometryError(double distanceScaleError, double rotationScaleError, double headingDriftRadPerM,
                            double distanceNoiseMPerSqrtM, double rotationNoiseRadPerSqrtRad) {

    /** No error: odometry is the ground truth (Stage's {@code localization "gps"}). */
    public static final OdometryError NONE = new OdometryError(0, 0, 0, 0, 0);

    /**
     * The Koala's: distance scale +-3 % (Stage's default x error; the Koala manual's 2.4 % tyre
     * compression), rotation scale +-8 % (skid steering, several times the distance error as the
     * skid-steer literature reports), heading drift +-0.01 rad/m, noise 0.01 m after 1 m and
     * 0.02 rad after 1 rad.
     */
    public static final OdometryError KOALA = new OdometryError(0.03, 0.08, 0.01, 0.01, 0.02);

    /**
     * @param distanceScaleError bound of the per-run distance scale error, a fraction (0.03 = 3 %)
     * @param rotationScaleError bound of the per-run rotation scale error, a fraction
     * @param headingDriftRadPerM bound of the per-run heading drift per metre driven straight (unequal sides of
     *     a skid-steer base), radians per metre
     * @param distanceNoiseMPerSqrtM noise of the distance increments: standard deviation after one metre,
     *     metres per square-root metre
     * @param rotationNoiseRadPerSqrtRad noise of the rotation increments: standard deviation after one radian
     *     turned, radians per square-root radian
     * @throws IllegalArgumentException naming the field and the value if one is out of range
     */
    public OdometryError {
        fraction("distanceScaleError", distanceScaleError);
        fraction("rotationScaleError", rotationScaleError);
        RobotConfig.notNegative("headingDriftRadPerM", headingDriftRadPerM);
        RobotConfig.notNegative("distanceNoiseMPerSqrtM", distanceNoiseMPerSqrtM);
        RobotConfig.notNegative("rotationNoiseRadPerSqrtRad", rotationNoiseRadPerSqrtRad);
    }

    private static void fraction(String field, double value) {
        if (!(value >= 0 && value < 0.5)) {
            throw new IllegalArgumentException(field + " must be in [0, 0.5), got " + value);
        }
    }

    /** @return true if odometry equals the ground truth */
    public boolean isNone() {
        return equals(NONE);
    }
}
