package io.rtaware.sim.world;

import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;

/**
 * The simulated robot as a whole: its body and motion limits, how a velocity command reaches
 * the wheels, how its odometry errs and how its laser is timed. Two models are built in:
 * {@link #koala(double)}, the paper's K-Team Koala with a Hokuyo URG-04LX on Player, and
 * {@link #ideal(double)}, the exact point robot of earlier rtaware versions (commands act at
 * once, odometry is the ground truth, the laser is instantaneous), kept for tests and
 * comparisons. Immutable and validated.
 *
 * @param name {@value #KOALA_NAME} or {@value #IDEAL_NAME}
 * @param body the body, speed and acceleration limits of the hardware, odometry rate
 * @param maxDecelMps2 linear deceleration limit in m/s^2 (the acceleration limit is in
 *     {@code body}), positive
 * @param commandLatencyNs world time from a velocity command to the wheels starting to follow
 *     it, not negative
 * @param odometry how the odometry drifts
 * @param laserTiming when the laser's beams are measured and its scans delivered
 * @param topSpeedMps the top speed the controller is configured with (the paper's 0.1 m/s by
 *     default), positive, at most the body's {@code maxSpeedMps}
 */
public record RobotModel(String name, RobotConfig body, double maxDecelMps2, long commandLatencyNs,
                         OdometryError odometry, LaserTiming laserTiming, double topSpeedMps) {

    /** Name of the Koala model. */
    public static final String KOALA_NAME = "koala";
    /** Name of the ideal model. */
    public static final String IDEAL_NAME = "ideal";
    /** The paper's top speed, m/s ("the top speed of the robot being 0.1 meters per second"). */
    public static final double PAPER_TOP_SPEED_MPS = 0.1;
    /**
     * The Koala's top speed, m/s: 0.6 m/s in K-Team's Koala (II) product description, the
     * figure this project uses as the limit of {@code --top-speed}.
     */
    public static final double KOALA_MAX_SPEED_MPS = 0.6;

    /**
     * @param name {@value #KOALA_NAME} or {@value #IDEAL_NAME}
     * @param body the body, speed and acceleration limits of the hardware, odometry rate
     * @param maxDecelMps2 linear deceleration limit in m/s^2 (the acceleration limit is in {@code body}),
     *     positive
     * @param commandLatencyNs world time from a velocity command to the wheels starting to follow it, not
     *     negative
     * @param odometry how the odometry drifts
     * @param laserTiming when the laser's beams are measured and its scans delivered
     * @param topSpeedMps the top speed the controller is configured with (the paper's 0.1 m/s by default),
     *     positive, at most the body's {@code maxSpeedMps}
     * @throws IllegalArgumentException naming the field and the value if one is out of range
     */
    public RobotModel {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(body, "body");
        Objects.requireNonNull(odometry, "odometry");
        Objects.requireNonNull(laserTiming, "laserTiming");
        RobotConfig.positive("maxDecelMps2", maxDecelMps2);
        if (commandLatencyNs < 0) {
            throw new IllegalArgumentException("commandLatencyNs must not be negative, got " + commandLatencyNs);
        }
        RobotConfig.positive("topSpeedMps", topSpeedMps);
        if (topSpeedMps > body.maxSpeedMps()) {
            throw new IllegalArgumentException("topSpeedMps must not exceed the body's maxSpeedMps "
                    + body.maxSpeedMps() + ", got " + topSpeedMps);
        }
    }

    /**
     * The paper's robot. Body: radius 0.2 m (the Koala is 32 x 30 cm, K-Team), hardware top
     * speed {@value #KOALA_MAX_SPEED_MPS} m/s, turn rate 2 rad/s, acceleration 0.5 m/s^2 and
     * 2 rad/s^2, deceleration 1.0 m/s^2, odometry at 16 Hz (the paper: "position information
     * updates on average at 16Hz"). Acceleration and deceleration are estimates: the Koala 2.5
     * manual says its speed command changes speed "as quick as possible", limited by the 6 W
     * motors and the 58.5:1 gearbox, and offers an acceleration ramp instead; braking under
     * the 10 ms PID loop is faster than speeding up. Command latency 30 ms: Player's
     * position driver cycle plus the serial command and one or two 10 ms PID cycles of the
     * Koala's controller (an estimate). Odometry: {@link OdometryError#KOALA}. Laser:
     * {@link LaserTiming#URG_04LX}.
     *
     * @param topSpeedMps the controller's top speed, up to {@value #KOALA_MAX_SPEED_MPS}
     * @return the Koala model
     */
    public static RobotModel koala(double topSpeedMps) {
        RobotConfig body = new RobotConfig(0.2, KOALA_MAX_SPEED_MPS, 2.0, 0.5, 2.0, 16.0, 0.0, 0.0);
        return new RobotModel(KOALA_NAME, body, 1.0, 30_000_000L, OdometryError.KOALA, LaserTiming.URG_04LX,
                topSpeedMps);
    }

    /**
     * The ideal point robot of earlier versions: {@link RobotConfig#KOALA} with its top speed
     * set to {@code topSpeedMps}, deceleration equal to acceleration, no latency, exact
     * odometry, instantaneous scans. At the paper's 0.1 m/s it reproduces earlier trajectories
     * bit for bit.
     *
     * @param topSpeedMps top speed of the body and the controller
     * @return the ideal model
     */
    public static RobotModel ideal(double topSpeedMps) {
        return ideal(topSpeedMps == RobotConfig.KOALA.maxSpeedMps() ? RobotConfig.KOALA
                : new RobotConfig(RobotConfig.KOALA.radiusM(), topSpeedMps, RobotConfig.KOALA.maxTurnRateRadPerS(),
                        RobotConfig.KOALA.maxAccelMps2(), RobotConfig.KOALA.maxTurnAccelRadPerS2(),
                        RobotConfig.KOALA.odometryRateHz(), 0.0, 0.0));
    }

    /**
     * @param body a body whose top speed is also the controller's
     * @return an ideal robot with that body
     */
    public static RobotModel ideal(RobotConfig body) {
        return new RobotModel(IDEAL_NAME, body, body.maxAccelMps2(), 0L, OdometryError.NONE, LaserTiming.INSTANT,
                body.maxSpeedMps());
    }

    /**
     * @param name {@value #KOALA_NAME} or {@value #IDEAL_NAME}
     * @param topSpeedMps the controller's top speed
     * @return that built-in model
     * @throws IllegalArgumentException for another name or a top speed out of range
     */
    public static RobotModel named(String name, double topSpeedMps) {
        return switch (name) {
            case KOALA_NAME -> koala(topSpeedMps);
            case IDEAL_NAME -> ideal(topSpeedMps);
            default -> throw new IllegalArgumentException("robot model must be " + KOALA_NAME + " or " + IDEAL_NAME
                    + ", got '" + name + "'");
        };
    }

    /**
     * @param mps the controller's new top speed; for the ideal model also the body's
     * @return a copy with that top speed
     * @throws IllegalArgumentException if it is not positive or above the body's limit
     */
    public RobotModel withTopSpeed(double mps) {
        if (IDEAL_NAME.equals(name) && isIdeal()) {
            RobotConfig b = new RobotConfig(body.radiusM(), mps, body.maxTurnRateRadPerS(), body.maxAccelMps2(),
                    body.maxTurnAccelRadPerS2(), body.odometryRateHz(), body.odometryNoiseM(), body.odometryNoiseRad());
            return new RobotModel(name, b, maxDecelMps2, commandLatencyNs, odometry, laserTiming, mps);
        }
        return new RobotModel(name, body, maxDecelMps2, commandLatencyNs, odometry, laserTiming, mps);
    }

    /**
     * Overrides one numeric parameter by its report name (a key of {@link #parameters()}:
     * {@code top_speed_mps}, {@code accel_mps2}, {@code decel_mps2}, {@code command_latency_ms},
     * {@code odometry_*}, {@code laser_delivery_delay_ms}); a scenario's {@code robot:} section
     * uses the same names.
     *
     * @param key the parameter's name
     * @param value its new value
     * @return a copy with that parameter changed
     * @throws IllegalArgumentException for an unknown or derived name, or a value out of range
     */
    public RobotModel with(String key, double value) {
        OdometryError o = odometry;
        RobotConfig b = body;
        double decel = maxDecelMps2;
        long latency = commandLatencyNs;
        LaserTiming laser = laserTiming;
        switch (key) {
            case "top_speed_mps" -> {
                return withTopSpeed(value);
            }
            case "accel_mps2" -> b = new RobotConfig(b.radiusM(), b.maxSpeedMps(), b.maxTurnRateRadPerS(), value,
                    b.maxTurnAccelRadPerS2(), b.odometryRateHz(), b.odometryNoiseM(), b.odometryNoiseRad());
            case "decel_mps2" -> decel = value;
            case "command_latency_ms" -> latency = Math.round(value * 1e6);
            case "odometry_distance_scale_error" -> o = new OdometryError(value, o.rotationScaleError(),
                    o.headingDriftRadPerM(), o.distanceNoiseMPerSqrtM(), o.rotationNoiseRadPerSqrtRad());
            case "odometry_rotation_scale_error" -> o = new OdometryError(o.distanceScaleError(), value,
                    o.headingDriftRadPerM(), o.distanceNoiseMPerSqrtM(), o.rotationNoiseRadPerSqrtRad());
            case "odometry_heading_drift_rad_per_m" -> o = new OdometryError(o.distanceScaleError(),
                    o.rotationScaleError(), value, o.distanceNoiseMPerSqrtM(), o.rotationNoiseRadPerSqrtRad());
            case "odometry_distance_noise_m_per_sqrt_m" -> o = new OdometryError(o.distanceScaleError(),
                    o.rotationScaleError(), o.headingDriftRadPerM(), value, o.rotationNoiseRadPerSqrtRad());
            case "odometry_rotation_noise_rad_per_sqrt_rad" -> o = new OdometryError(o.distanceScaleError(),
                    o.rotationScaleError(), o.headingDriftRadPerM(), o.distanceNoiseMPerSqrtM(), value);
            case "laser_delivery_delay_ms" -> laser = new LaserTiming(laser.sweep(), Math.round(value * 1e6),
                    LaserTiming.Link.NONE);
            default -> throw new IllegalArgumentException("unknown robot parameter '" + key + "' (known: top_speed_mps, "
                    + "accel_mps2, decel_mps2, command_latency_ms, odometry_distance_scale_error, "
                    + "odometry_rotation_scale_error, odometry_heading_drift_rad_per_m, "
                    + "odometry_distance_noise_m_per_sqrt_m, odometry_rotation_noise_rad_per_sqrt_rad, "
                    + "laser_delivery_delay_ms, laser_link)");
        }
        return new RobotModel(name, b, decel, latency, o, laser, topSpeedMps);
    }

    /**
     * @param link the link the laser's scans travel over
     * @return a copy whose sweeping laser delivers with that link's delay (the ideal model's
     *     instantaneous laser is kept)
     */
    public RobotModel withLaserLink(LaserTiming.Link link) {
        if (!laserTiming.sweep()) {
            return this;
        }
        return new RobotModel(name, body, maxDecelMps2, commandLatencyNs, odometry, LaserTiming.urg04lx(link),
                topSpeedMps);
    }

    /** @return true for a model without latency, odometry error or laser sweep */
    public boolean isIdeal() {
        return commandLatencyNs == 0 && odometry.isNone() && !laserTiming.sweep()
                && maxDecelMps2 == body.maxAccelMps2();
    }

    /**
     * The distance the robot needs to stop from {@code speedMps}: it keeps going for the
     * command latency, then brakes at {@link #maxDecelMps2()}.
     *
     * @param speedMps the speed it is stopping from, m/s
     * @return the stopping distance in metres
     */
    public double stoppingDistanceM(double speedMps) {
        double v = Math.abs(speedMps);
        return v * commandLatencyNs * 1e-9 + v * v / (2 * maxDecelMps2);
    }

    /**
     * How old a scan already is when it is delivered: for a sweeping laser, from its first beam
     * to delivery ({@code (beams - 1)} beam intervals plus the delivery delay: 76.6 ms for the
     * URG-04LX); 0 for an instantaneous one.
     *
     * @param laser the laser
     * @return the age at delivery in world nanoseconds
     */
    public long laserDelayNs(LaserConfig laser) {
        if (!laserTiming.sweep()) {
            return 0L;
        }
        double beamNs = laser.periodNs() * laser.angleIncrementRad() / (2 * Math.PI);
        return (long) ((laser.beams() - 1) * beamNs) + laserTiming.deliveryDelayNs();
    }

    /**
     * The model's parameters by name, for reports ({@code run.robot_model}), in a fixed order.
     *
     * @return a new map from parameter name (with its unit) to value
     */
    public Map<String, Object> parameters() {
        Map<String, Object> p = new LinkedHashMap<>();
        p.put("name", name);
        p.put("top_speed_mps", topSpeedMps);
        p.put("max_speed_mps", body.maxSpeedMps());
        p.put("max_turn_rate_rad_per_s", body.maxTurnRateRadPerS());
        p.put("radius_m", body.radiusM());
        p.put("accel_mps2", body.maxAccelMps2());
        p.put("decel_mps2", maxDecelMps2);
        p.put("turn_accel_rad_per_s2", body.maxTurnAccelRadPerS2());
        p.put("command_latency_ms", commandLatencyNs / 1e6);
        p.put("odometry_rate_hz", body.odometryRateHz());
        p.put("odometry_distance_scale_error", odometry.distanceScaleError());
        p.put("odometry_rotation_scale_error", odometry.rotationScaleError());
        p.put("odometry_heading_drift_rad_per_m", odometry.headingDriftRadPerM());
        p.put("odometry_distance_noise_m_per_sqrt_m", odometry.distanceNoiseMPerSqrtM());
        p.put("odometry_rotation_noise_rad_per_sqrt_rad", odometry.rotationNoiseRadPerSqrtRad());
        p.put("laser_sweep", laserTiming.sweep());
        p.put("laser_link", laserTiming.link().jsonName());
        p.put("laser_delivery_delay_ms", laserTiming.deliveryDelayNs() / 1e6);
        p.put("stopping_distance_m", stoppingDistanceM(topSpeedMps));
        return p;
    }

    /**
     * Where each of the Koala's parameters comes from: every key of {@link #parameters()} but
     * {@code name}, with a text that starts with {@code source:} (a document or the paper) or
     * {@code estimate:} (our reasoning where no document gives the number). Reports carry it
     * as {@code run.robot_model.sources}; docs/robot-model.md has the same table.
     *
     * @return a new map from parameter name to its source, in the order of {@link #parameters()}
     */
    public static Map<String, String> sources() {
        Map<String, String> s = new LinkedHashMap<>();
        s.put("top_speed_mps", "source: the paper, 'the top speed of the robot being 0.1 meters per second'");
        s.put("max_speed_mps", "source: K-Team's Koala product description gives 0.6 m/s (vendor figure; no stored copy of "
                + "the data sheet was found, so unverified here); the limit of --top-speed");
        s.put("max_turn_rate_rad_per_s", "estimate: both sides at 0.3 m/s in opposite directions on a track of about "
                + "0.3 m (the body is 32 x 30 cm) turn at 2 rad/s");
        s.put("radius_m", "source: K-Team gives the Koala's body as about 32 x 30 cm; 0.2 m is the half diagonal rounded");
        s.put("accel_mps2", "estimate: the Koala 2.5 manual says its speed command (PID every 10 ms) changes speed "
                + "'as quick as possible', limited by the 6 W motors and 58.5:1 gearbox, and offers a ramp mode instead");
        s.put("decel_mps2", "estimate: braking under the 10 ms PID loop is faster than speeding up: twice the acceleration");
        s.put("turn_accel_rad_per_s2", "estimate: the linear acceleration at the wheels over half the track, reduced for "
                + "the slip of skid steering");
        s.put("command_latency_ms", "estimate: Player's position driver cycle, the serial command to the Koala, one or "
                + "two 10 ms PID cycles of its controller");
        s.put("odometry_rate_hz", "source: the paper, position information 'updates on average at 16Hz'");
        s.put("odometry_distance_scale_error", "estimate: drawn once per robot in +-e; Stage's position model draws its "
                + "x error in +-E/2 of odom_error (default 0.03, so +-0.015); the Koala 2.5 manual: the 82.5 mm wheel "
                + "compresses to 80.5 mm under 3 kg, a 2.4 % distance error until recalibrated, so e = 0.03 covers it");
        s.put("odometry_rotation_scale_error", "estimate: skid steering turns by slipping, so the encoders' rotation is "
                + "off by the slip, several times the distance error (Mandow et al., IROS 2007, 'Experimental kinematics "
                + "for wheeled skid-steer mobile robots'); Stage's heading odom_error default 0.05 is for a differential drive");
        s.put("odometry_heading_drift_rad_per_m", "estimate: unequal sides of a skid-steer base bend a straight line; "
                + "0.01 rad/m (0.6 degree per metre) is our guess of its size, no source gives one for the Koala");
        s.put("odometry_distance_noise_m_per_sqrt_m", "estimate: 1 cm after 1 m of zero-mean random walk, a third of the "
                + "systematic bound; no source measured the Koala's");
        s.put("odometry_rotation_noise_rad_per_sqrt_rad", "estimate: 0.02 rad after 1 rad turned, twice the distance "
                + "noise as skid steering slips more when turning; no source measured the Koala's");
        s.put("laser_sweep", "source: SCIP 2.0 specification, the URG-04LX answers PP with SCAN:600 (600 rpm, 100 ms per "
                + "turn), ARES:1024, AMIN:44, AMAX:725: its 683 steps take 66.6 ms, each measured where the robot is then");
        s.put("laser_link", "assumption: usb. The paper says the Hokuyo 'sends out its data at a rate of 10Hz'; over "
                + "RS-232 at 115.2 kbit/s a full scan (about 1 430 bytes) takes 124 ms and could not arrive at 10 Hz, so "
                + "the paper's URG was on USB; serial is available as robot: {laser_link: serial}");
        s.put("laser_delivery_delay_ms", "derived from laser_link: serial 124 ms (1 430 bytes at 11 520 bytes/s); usb "
                + "10 ms, an estimate (the bus takes under 2 ms, plus the sensor's preparation and the driver's read)");
        s.put("stopping_distance_m", "derived: top speed x command latency + top speed^2 / (2 x deceleration)");
        return s;
    }

    /** @return a one-line description for logs */
    public String describe() {
        return String.format(Locale.ROOT, "%s (top speed %.2f m/s)", name, topSpeedMps);
    }
}
