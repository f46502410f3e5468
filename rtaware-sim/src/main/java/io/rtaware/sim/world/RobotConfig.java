package io.rtaware.sim.world;

/**
 * The simulated robot's body, motion limits and odometry. Immutable, validated, thread-safe.
 *
 * @param radiusM collision radius in metres, positive
 * @param maxSpeedMps top forward/backward speed in m/s, positive
 * @param maxTurnRateRadPerS top turn rate in rad/s, positive
 * @param maxAccelMps2 linear acceleration limit in m/s^2, positive
 * @param maxTurnAccelRadPerS2 angular acceleration limit in rad/s^2, positive
 * @param odometryRateHz how often odometry is published, in world-time Hz, positive
 * @param odometryNoiseM standard deviation of the Gaussian noise added to each reported x and
 *     y, in metres, not negative (0 = exact)
 * @param odometryNoiseRad standard deviation of the noise added to each reported heading, in
 *     radians, not negative
 */
public record RobotConfig(double radiusM, double maxSpeedMps, double maxTurnRateRadPerS, double maxAccelMps2,
                          double maxTurnAccelRadPerS2, double odometryRateHz, double odometryNoiseM,
                          double odometryNoiseRad) {

    /** The paper's Koala: radius 0.2 m, 0.1 m/s, 0.5 rad/s, 0.5 m/s^2, 2 rad/s^2, 16 Hz, no noise. */
    public static final RobotConfig KOALA = new RobotConfig(0.2, 0.1, 0.5, 0.5, 2.0, 16.0, 0.0, 0.0);

    /**
     * @param radiusM collision radius in metres, positive
     * @param maxSpeedMps top forward/backward speed in m/s, positive
     * @param maxTurnRateRadPerS top turn rate in rad/s, positive
     * @param maxAccelMps2 linear acceleration limit in m/s^2, positive
     * @param maxTurnAccelRadPerS2 angular acceleration limit in rad/s^2, positive
     * @param odometryRateHz how often odometry is published, in world-time Hz, positive
     * @param odometryNoiseM standard deviation of the Gaussian noise added to each reported x and y, in metres,
     *     not negative (0 = exact)
     * @param odometryNoiseRad standard deviation of the noise added to each reported heading, in radians, not
     *     negative
     * @throws IllegalArgumentException naming the field and the value if one is out of range
     */
    public RobotConfig {
        positive("radiusM", radiusM);
        positive("maxSpeedMps", maxSpeedMps);
        positive("maxTurnRateRadPerS", maxTurnRateRadPerS);
        positive("maxAccelMps2", maxAccelMps2);
        positive("maxTurnAccelRadPerS2", maxTurnAccelRadPerS2);
        positive("odometryRateHz", odometryRateHz);
        notNegative("odometryNoiseM", odometryNoiseM);
        notNegative("odometryNoiseRad", odometryNoiseRad);
    }

    /**
     * @param noiseM new {@link #odometryNoiseM}
     * @param noiseRad new {@link #odometryNoiseRad}
     * @return a copy with different odometry noise
     */
    public RobotConfig withOdometryNoise(double noiseM, double noiseRad) {
        return new RobotConfig(radiusM, maxSpeedMps, maxTurnRateRadPerS, maxAccelMps2, maxTurnAccelRadPerS2,
                odometryRateHz, noiseM, noiseRad);
    }

    /** @return the odometry period in world nanoseconds */
    public long odometryPeriodNs() {
        return Math.max(1L, Math.round(1e9 / odometryRateHz));
    }

    static void positive(String field, double value) {
        if (!(value > 0) || Double.isInfinite(value)) {
            throw new IllegalArgumentException(field + " must be positive and finite, got " + value);
        }
    }

    static void notNegative(String field, double value) {
        if (!(value >= 0) || Double.isInfinite(value)) {
            throw new IllegalArgumentException(field + " must be finite and not negative, got " + value);
        }
    }
}
