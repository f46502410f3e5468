package io.rtaware.sim.world;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.SplittableRandom;

/**
 * One robot's systematic odometry errors: the flaws of its wheels and encoders, which stay the
 * same from run to run (the paper's trials were all made with one Koala). Drawn once per robot
 * from a robot seed ({@link #draw(OdometryError, long)}), each uniformly in {@code [-e, +e]} of
 * its {@link OdometryError} bound; the per-run noise is separate and comes from the run's seed.
 * Immutable.
 *
 * @param distanceScale factor on every distance the encoders measure (1.02 = 2 % long)
 * @param rotationScale factor on every rotation the encoders measure
 * @param headingDriftRadPerM heading error added per metre driven, radians per metre
 */
public record OdometryBias(double distanceScale, double rotationScale, double headingDriftRadPerM) {

    /** No systematic error. */
    public static final OdometryBias NONE = new OdometryBias(1.0, 1.0, 0.0);

    private static final long ROBOT_SEED_SALT = 0x165667B19E3779F9L;

    /**
     * Draws a robot's systematic errors: the same {@code robotSeed} and bounds give the same
     * robot, whatever the run.
     *
     * @param bounds the error model's bounds
     * @param robotSeed the robot's seed ({@code --robot-seed})
     * @return the robot's errors; {@link #NONE}'s values for bounds of 0
     */
    public static OdometryBias draw(OdometryError bounds, long robotSeed) {
        SplittableRandom random = new SplittableRandom(robotSeed ^ ROBOT_SEED_SALT);
        return new OdometryBias(1.0 + uniform(random, bounds.distanceScaleError()),
                1.0 + uniform(random, bounds.rotationScaleError()), uniform(random, bounds.headingDriftRadPerM()));
    }

    /** A draw from [-bound, bound], or exactly 0 for a bound of 0 (the draw is still made, so later draws do not shift). */
    private static double uniform(SplittableRandom random, double bound) {
        double u = random.nextDouble();
        return bound == 0 ? 0.0 : bound * (2 * u - 1);
    }

    /**
     * @return the errors for reports ({@code run.robot_errors}): {@code distance_scale_error},
     *     {@code rotation_scale_error} (fractions) and {@code heading_drift_rad_per_m}
     */
    public Map<String, Object> parameters() {
        Map<String, Object> p = new LinkedHashMap<>();
        p.put("distance_scale_error", distanceScale - 1.0);
        p.put("rotation_scale_error", rotationScale - 1.0);
        p.put("heading_drift_rad_per_m", headingDriftRadPerM);
        return p;
    }
}
