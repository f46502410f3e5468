package io.rtaware.sim.world;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The simulated planar laser, mounted at the robot's centre looking forward. Beams are spread
 * evenly and symmetrically about the heading: beam {@code i} points at
 * {@code -fov/2 + i * angleIncrementRad} with {@code fov = (beams - 1) * angleIncrementRad}.
 * Immutable, validated, thread-safe.
 *
 * @param beams number of beams, 1..4096
 * @param angleIncrementRad angle between neighbouring beams in radians, positive; the field of
 *     view {@code (beams - 1) * angleIncrementRad} must not exceed 2 pi
 * @param minRangeM shortest reported range in metres, not negative
 * @param maxRangeM longest range in metres, above {@code minRangeM}; beams that hit nothing
 *     report exactly this
 * @param rateHz scans per world-time second, positive
 * @param noiseSigmaM standard deviation of the Gaussian range noise in metres, not negative
 */
public record LaserConfig(int beams, double angleIncrementRad, double minRangeM, double maxRangeM,
                          double rateHz, double noiseSigmaM) {

    /**
     * Hokuyo URG-04LX-like: 683 beams 0.3515625 deg (360/1024) apart, i.e. 240 deg nominal field
     * of view (239.77 deg between the outer beams), 0.02..5.6 m (the sensor's SCIP 2.0 {@code PP}
     * answer, {@code DMIN:20}, {@code DMAX:5600}), 10 Hz, 1 cm noise.
     */
    public static final LaserConfig URG_04LX =
            new LaserConfig(683, Math.toRadians(360.0 / 1024.0), 0.02, 5.6, 10.0, 0.01);

    /**
     * @param beams number of beams, 1..4096
     * @param angleIncrementRad angle between neighbouring beams in radians, positive; the field of view {@code
     *     (beams - 1) * angleIncrementRad} must not exceed 2 pi
     * @param minRangeM shortest reported range in metres, not negative
     * @param maxRangeM longest range in metres, above {@code minRangeM}; beams that hit nothing report exactly
     *     this
     * @param rateHz scans per world-time second, positive
     * @param noiseSigmaM standard deviation of the Gaussian range noise in metres, not negative
     * @throws IllegalArgumentException naming the field and the value if one is out of range
     */
    public LaserConfig {
        if (beams < 1 || beams > 4096) {
            throw new IllegalArgumentException("beams must be in 1..4096, got " + beams);
        }
        RobotConfig.positive("angleIncrementRad", angleIncrementRad);
        if ((beams - 1) * angleIncrementRad > 2 * Math.PI + 1e-9) {
            throw new IllegalArgumentException("angleIncrementRad gives a field of view above 2 pi, got "
                    + angleIncrementRad);
        }
        RobotConfig.notNegative("minRangeM", minRangeM);
        RobotConfig.positive("maxRangeM", maxRangeM);
        if (maxRangeM <= minRangeM) {
            throw new IllegalArgumentException("maxRangeM must exceed minRangeM " + minRangeM + ", got " + maxRangeM);
        }
        RobotConfig.positive("rateHz", rateHz);
        RobotConfig.notNegative("noiseSigmaM", noiseSigmaM);
    }

    /**
     * @param sigmaM new {@link #noiseSigmaM}
     * @return a copy with different range noise
     */
    public LaserConfig withNoise(double sigmaM) {
        return new LaserConfig(beams, angleIncrementRad, minRangeM, maxRangeM, rateHz, sigmaM);
    }

    /** @return the angle between the first and the last beam in radians */
    public double fovRad() {
        return (beams - 1) * angleIncrementRad;
    }

    /** @return bearing of the first beam in radians (negative: to the right) */
    public double minAngleRad() {
        return -fovRad() / 2;
    }

    /** @return bearing of the last beam in radians */
    public double maxAngleRad() {
        return fovRad() / 2;
    }

    /**
     * @return the laser's parameters for reports ({@code run.robot_model}): {@code laser_beams},
     *     {@code laser_angle_increment_rad}, {@code laser_min_range_m}, {@code laser_max_range_m},
     *     {@code laser_rate_hz}, {@code laser_range_noise_m}
     */
    public Map<String, Object> parameters() {
        Map<String, Object> p = new LinkedHashMap<>();
        p.put("laser_beams", beams);
        p.put("laser_angle_increment_rad", angleIncrementRad);
        p.put("laser_min_range_m", minRangeM);
        p.put("laser_max_range_m", maxRangeM);
        p.put("laser_rate_hz", rateHz);
        p.put("laser_range_noise_m", noiseSigmaM);
        return p;
    }

    /**
     * Where the {@link #URG_04LX} parameters come from, keyed as {@link #parameters()}; each text
     * starts with {@code source:} or {@code estimate:}.
     *
     * @return a new map from parameter name to its source
     */
    public static Map<String, String> urg04lxSources() {
        Map<String, String> s = new LinkedHashMap<>();
        s.put("laser_beams", "source: SCIP 2.0, the URG-04LX's PP answer AMIN:44, AMAX:725: 683 steps");
        s.put("laser_angle_increment_rad", "source: SCIP 2.0, ARES:1024 steps per turn, 0.3515625 degree");
        s.put("laser_min_range_m", "source: SCIP 2.0 PP answer of the URG-04LX, DMIN:20 (mm)");
        s.put("laser_max_range_m", "source: SCIP 2.0 PP answer of the URG-04LX, DMAX:5600 (mm): the longest range the "
                + "sensor reports (Hokuyo quotes 4 m for the model; the sensor itself reports ranges up to DMAX)");
        s.put("laser_rate_hz", "source: the paper, 'the Hokuyo laser sends out its data at a rate of 10Hz' (600 rpm)");
        s.put("laser_range_noise_m", "estimate: 1 cm standard deviation, the order of the URG-04LX's quoted accuracy "
                + "at short range (about +-10 mm); not measured on the paper's unit");
        return s;
    }

    /** @return the scan period in world nanoseconds */
    public long periodNs() {
        return Math.max(1L, Math.round(1e9 / rateHz));
    }
}
