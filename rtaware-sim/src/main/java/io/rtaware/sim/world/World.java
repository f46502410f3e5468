package io.rtaware.sim.world;

import io.rtaware.robot.geometry.Angles;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.sim.actor.ActorSpec;
import io.rtaware.sim.actor.Actors;
import io.rtaware.sim.map.OccupancyMap;
import io.rtaware.sim.map.RayCaster;
import java.util.List;
import java.util.Objects;
import java.util.SplittableRandom;

/**
 * One robot in one map, advanced by {@link #step(long)} with a world-time step.
 *
 * <p>The robot follows the commanded forward speed and turn rate within its speed and
 * acceleration limits, integrating exact arcs in sub-steps of at most {@value #MAX_SUBSTEP_M} m
 * so it cannot tunnel through thin walls. A sub-step that would bring the robot's disc into an
 * obstacle is cut at the contact point (found by bisection): the robot stops there, its forward
 * speed drops to zero, {@link #stalled()} is true for that step, and a new contact is counted
 * once per contact event (a contact ends when the robot is more than
 * {@value #CONTACT_RELEASE_M} m clear again). Turning on the spot is never blocked (the body is
 * a disc). Moves that increase the clearance are always allowed, so a robot placed inside an
 * obstacle can drive out.
 *
 * <p>Odometry and laser scans are produced at their world-time rates; the step that produced
 * one sets {@link #odometryFresh()} / {@link #scanFresh()}. Both are also produced at time zero.
 * Same seed, same commands and same steps give bit-identical results.
 *
 * <p>The {@link RobotModel} decides how real the robot is. The ideal model follows a command
 * at once, reports its true pose as odometry (like Stage with {@code gps} localization, with
 * optional seeded white noise) and takes each scan at one instant. The Koala model applies a
 * command after the model's latency, brakes at its own deceleration limit, dead-reckons its
 * odometry from the true motion with per-run scale errors and noise ({@link OdometryError}:
 * the odometry starts at the start pose in the world frame and drifts from there), and sweeps
 * each scan's beams over the laser's turn, delivering it later ({@link LaserTiming}).
 *
 * <p>Not thread-safe: one thread owns a world (the server's sim thread or a test).
 */
public final class World {

    /** Longest distance travelled in one integration sub-step, metres. */
    public static final double MAX_SUBSTEP_M = 0.005;
    /** Clearance beyond the radius, in metres, at which a contact is over. */
    public static final double CONTACT_RELEASE_M = 0.01;
    /**
     * A near miss: the robot's body came within this many metres of an obstacle (map or actor)
     * without touching it; one per approach, over when the clearance is back above the margin
     * plus {@value #CONTACT_RELEASE_M} m.
     */
    public static final double NEAR_MISS_MARGIN_M = 0.05;
    /** Clearances beyond this many metres are not measured exactly ({@link #minClearanceM()} says "at least"). */
    public static final double CLEARANCE_LIMIT_M = 0.5;

    private static final int BISECTION_STEPS = 12;
    private static final long ODOMETRY_SEED_SALT = 0x9E3779B97F4A7C15L;
    private static final long DRIFT_SEED_SALT = 0xC2B2AE3D27D4EB4FL;
    /** Commands waiting for the latency to pass; a newer command beyond this drops the oldest. */
    private static final int MAX_PENDING_COMMANDS = 256;

    private final OccupancyMap map;
    private final Actors actors;
    private final RobotModel model;
    private final RobotConfig robot;
    private final Laser laser;
    private final SplittableRandom laserNoise;
    private final SplittableRandom odometryNoise;
    private final Odometry odometry = new Odometry();
    private final LaserScan scan;
    private final long odometryPeriodNs;
    private final long laserPeriodNs;
    private final SplittableRandom driftNoise;
    /** The robot's systematic odometry errors, drawn from the robot seed. */
    private final OdometryBias bias;
    private final double distanceScale;
    private final double rotationScale;
    private final double headingDriftRadPerM;
    private final long[] pendingDueNs = new long[MAX_PENDING_COMMANDS];
    private final double[] pendingV = new double[MAX_PENDING_COMMANDS];
    private final double[] pendingW = new double[MAX_PENDING_COMMANDS];
    private int pendingHead;
    private int pendingCount;
    private final LaserScan sweepScan;
    private final double beamIntervalNs;
    private long sweepStartNs;
    private int sweepNextBeam;
    private long sweepDeliveryNs = -1;
    /** World time at which the latest scan's first beam was measured. */
    private long scanFirstBeamNs;
    private double odoXM;
    private double odoYM;
    private double odoYawRad;

    private long timeNs;
    private double xM;
    private double yM;
    private double yawRad;
    private double vMps;
    private double omegaRadPerS;
    private double cmdVMps;
    private double cmdOmegaRadPerS;
    private boolean motorsEnabled = true;
    private boolean stalled;
    private boolean inContact;
    private long contactCount;
    private double minClearanceM = CLEARANCE_LIMIT_M;
    private boolean nearMissOpen;
    private boolean nearMissTouched;
    private long nearMisses;
    private boolean odometryFresh;
    private boolean scanFresh;
    private long nextOdometryNs;
    private long nextScanNs;

    /**
     * Creates the world at time zero with the robot at {@code start}, publishing a first
     * odometry and scan.
     *
     * @param map the world map
     * @param start the robot's initial pose
     * @param robot the robot's parameters
     * @param laserConfig the laser's parameters
     * @param seed seed of all noise
     */
    public World(OccupancyMap map, Pose2d start, RobotConfig robot, LaserConfig laserConfig, long seed) {
        this(map, start, RobotModel.ideal(Objects.requireNonNull(robot, "robot")), laserConfig, seed);
    }

    /**
     * Creates the world at time zero with the robot at {@code start}, publishing a first
     * odometry and scan.
     *
     * @param map the world map
     * @param start the robot's initial pose (also the odometry's starting estimate)
     * @param model the robot model
     * @param laserConfig the laser's parameters
     * @param seed seed of all noise and also of the robot's systematic odometry errors (a new robot per seed)
     */
    public World(OccupancyMap map, Pose2d start, RobotModel model, LaserConfig laserConfig, long seed) {
        this(map, start, model, laserConfig, seed, seed);
    }

    /**
     * Creates the world at time zero with the robot at {@code start}, publishing a first
     * odometry and scan.
     *
     * @param map the world map
     * @param start the robot's initial pose (also the odometry's starting estimate)
     * @param model the robot model
     * @param laserConfig the laser's parameters
     * @param seed seed of this run's noise (laser ranges, odometry increments)
     * @param robotSeed seed of the robot's systematic odometry errors ({@link OdometryBias}): the
     *     same robot seed is the same robot in every run
     */
    public World(OccupancyMap map, Pose2d start, RobotModel model, LaserConfig laserConfig, long seed,
                 long robotSeed) {
        this(map, start, model, laserConfig, seed, robotSeed, List.of());
    }

    /**
     * Creates the world at time zero with the robot at {@code start} and the scenario's actors,
     * publishing a first odometry and scan.
     *
     * @param map the world map
     * @param start the robot's initial pose (also the odometry's starting estimate)
     * @param model the robot model
     * @param laserConfig the laser's parameters
     * @param seed seed of this run's noise and of the actors' start jitter
     * @param robotSeed seed of the robot's systematic odometry errors
     * @param actorSpecs the actors: in the ground truth, the laser, collisions and clearance
     */
    public World(OccupancyMap map, Pose2d start, RobotModel model, LaserConfig laserConfig, long seed,
                 long robotSeed, List<ActorSpec> actorSpecs) {
        this.map = Objects.requireNonNull(map, "map");
        this.model = Objects.requireNonNull(model, "model");
        this.robot = model.body();
        this.actors = new Actors(actorSpecs, seed);
        RayCaster walls = new RayCaster(map);
        this.laser = new Laser(Objects.requireNonNull(laserConfig, "laserConfig"), actors.isEmpty() ? walls
                : (x, y, dx, dy, max) -> actors.castM(x, y, dx, dy, walls.castM(x, y, dx, dy, max)));
        this.scan = new LaserScan(laserConfig.beams());
        this.sweepScan = new LaserScan(laserConfig.beams());
        this.laserNoise = new SplittableRandom(seed);
        this.odometryNoise = new SplittableRandom(seed ^ ODOMETRY_SEED_SALT);
        this.driftNoise = new SplittableRandom(seed ^ DRIFT_SEED_SALT);
        this.bias = OdometryBias.draw(model.odometry(), robotSeed);
        this.distanceScale = bias.distanceScale();
        this.rotationScale = bias.rotationScale();
        this.headingDriftRadPerM = bias.headingDriftRadPerM();
        this.odometryPeriodNs = robot.odometryPeriodNs();
        this.laserPeriodNs = laserConfig.periodNs();
        this.beamIntervalNs = laserPeriodNs * laserConfig.angleIncrementRad() / (2 * Math.PI);
        actors.update(0L, start.xM(), start.yM());
        placeAt(start);
        measureClearance();
        odoXM = xM;
        odoYM = yM;
        odoYawRad = yawRad;
        publishOdometry();
        publishScan();
        nextOdometryNs = odometryPeriodNs;
        nextScanNs = laserPeriodNs;
    }

    /**
     * Sets the commanded velocity, clamped to the robot's speed limits. Non-finite values
     * are taken as zero.
     *
     * @param vMps forward speed in m/s
     * @param omegaRadPerS turn rate in rad/s, counter-clockwise positive
     */
    public void command(double vMps, double omegaRadPerS) {
        double v = clamp(Double.isFinite(vMps) ? vMps : 0.0, robot.maxSpeedMps());
        double w = clamp(Double.isFinite(omegaRadPerS) ? omegaRadPerS : 0.0, robot.maxTurnRateRadPerS());
        if (model.commandLatencyNs() == 0) {
            this.cmdVMps = v;
            this.cmdOmegaRadPerS = w;
            return;
        }
        if (pendingCount == MAX_PENDING_COMMANDS) {
            pendingHead = (pendingHead + 1) % MAX_PENDING_COMMANDS;
            pendingCount--;
        }
        int at = (pendingHead + pendingCount) % MAX_PENDING_COMMANDS;
        pendingDueNs[at] = timeNs + model.commandLatencyNs();
        pendingV[at] = v;
        pendingW[at] = w;
        pendingCount++;
    }

    /** Moves every pending command due by {@code nowNs} to the wheels, in order. */
    private void applyDueCommands(long nowNs) {
        while (pendingCount > 0 && pendingDueNs[pendingHead] <= nowNs) {
            cmdVMps = pendingV[pendingHead];
            cmdOmegaRadPerS = pendingW[pendingHead];
            pendingHead = (pendingHead + 1) % MAX_PENDING_COMMANDS;
            pendingCount--;
        }
    }

    /** @return the robot model */
    public RobotModel model() {
        return model;
    }

    /** @return the robot's systematic odometry errors (drawn from the robot seed) */
    public OdometryBias odometryBias() {
        return bias;
    }

    /** @return the forward speed the wheels are following now (after the latency), m/s */
    public double wheelCommandMps() {
        return cmdVMps;
    }

    /**
     * Switches the motors on or off (Player MOTOR_POWER); off means the command is ignored
     * and the robot decelerates to a stop.
     *
     * @param enabled true for on
     */
    public void setMotorsEnabled(boolean enabled) {
        this.motorsEnabled = enabled;
    }

    /** @return true if the motors are on */
    public boolean motorsEnabled() {
        return motorsEnabled;
    }

    /**
     * Teleports the robot (Player simulation SET_POSE2D), stopping it. No collision check: a
     * pose inside an obstacle is allowed, and moves away from it are then permitted.
     *
     * @param pose the new ground-truth pose
     */
    public void setPose(Pose2d pose) {
        placeAt(pose);
        vMps = 0.0;
        omegaRadPerS = 0.0;
    }

    /**
     * @return the robot's own pose estimate (its odometry, updated every sub-step, not only
     *     when published), allocates; for the ideal model the ground truth
     */
    public Pose2d odometryPose() {
        return model.odometry().isNone() ? pose() : new Pose2d(odoXM, odoYM, odoYawRad);
    }

    /**
     * Advances the world by {@code dtNs} of world time.
     *
     * @param dtNs the step in world nanoseconds, not negative
     * @throws IllegalArgumentException if {@code dtNs} is negative
     */
    public void step(long dtNs) {
        if (dtNs < 0) {
            throw new IllegalArgumentException("dtNs must not be negative, got " + dtNs);
        }
        odometryFresh = false;
        scanFresh = false;
        stalled = false;
        double dtS = dtNs * 1e-9;
        int substeps = (int) Math.max(1L, (long) Math.ceil(robot.maxSpeedMps() * dtS / MAX_SUBSTEP_M));
        double h = dtS / substeps;
        boolean dead = !model.odometry().isNone();
        for (int i = 0; i < substeps && dtNs > 0; i++) {
            long subNs = timeNs + (long) (i * (double) dtNs / substeps);
            if (pendingCount > 0) {
                applyDueCommands(subNs);
            }
            if (!actors.isEmpty()) {
                actors.update(subNs, xM, yM);
                touchedByActor();
            }
            double targetV = motorsEnabled ? cmdVMps : 0.0;
            double targetW = motorsEnabled ? cmdOmegaRadPerS : 0.0;
            double accel = braking(vMps, targetV) ? model.maxDecelMps2() : robot.maxAccelMps2();
            vMps = approach(vMps, targetV, accel * h);
            omegaRadPerS = approach(omegaRadPerS, targetW, robot.maxTurnAccelRadPerS2() * h);
            if (dead) {
                double x0 = xM;
                double y0 = yM;
                double yaw0 = yawRad;
                integrate(h);
                deadReckon(x0, y0, yaw0);
            } else {
                integrate(h);
            }
        }
        if (!actors.isEmpty()) {
            actors.update(timeNs + dtNs, xM, yM);
            touchedByActor();
        }
        if (inContact && clearanceM(xM, yM, robot.radiusM() + 2 * CONTACT_RELEASE_M)
                > robot.radiusM() + CONTACT_RELEASE_M) {
            inContact = false;
        }
        measureClearance();
        timeNs += dtNs;
        if (pendingCount > 0) {
            applyDueCommands(timeNs);
        }
        if (timeNs >= nextOdometryNs) {
            publishOdometry();
            nextOdometryNs = nextDue(nextOdometryNs, odometryPeriodNs);
        }
        if (model.laserTiming().sweep()) {
            sweep();
        } else if (timeNs >= nextScanNs) {
            publishScan();
            nextScanNs = nextDue(nextScanNs, laserPeriodNs);
        }
    }

    /** The clearance of a point from the map's obstacles and the present actors. */
    private double clearanceM(double x, double y, double limitM) {
        double c = map.clearanceM(x, y, limitM);
        return actors.isEmpty() ? c : Math.min(c, actors.clearanceM(x, y));
    }

    /** An actor that moved into the standing or slower robot is a contact too. */
    private void touchedByActor() {
        if (!inContact && actors.clearanceM(xM, yM) < robot.radiusM()) {
            inContact = true;
            contactCount++;
        }
    }

    /** Keeps the smallest clearance of the robot's body and counts near misses (approaches within the margin that do not touch). */
    private void measureClearance() {
        double radius = robot.radiusM();
        // Exact only as far as it matters (below the smallest so far, or the near-miss margin):
        // the map's clearance is O(1) beyond its limit, so this costs little away from obstacles.
        double needM = Math.max(minClearanceM, NEAR_MISS_MARGIN_M + 2 * CONTACT_RELEASE_M);
        double gap = Math.max(0.0, clearanceM(xM, yM, radius + needM) - radius);
        minClearanceM = Math.min(minClearanceM, gap);
        if (gap < NEAR_MISS_MARGIN_M) {
            if (!nearMissOpen) {
                nearMissOpen = true;
                nearMissTouched = false;
            }
            nearMissTouched |= inContact;
        } else if (nearMissOpen && gap > NEAR_MISS_MARGIN_M + CONTACT_RELEASE_M) {
            nearMissOpen = false;
            if (!nearMissTouched) {
                nearMisses++;
            }
        }
    }

    private static boolean braking(double v, double target) {
        return Math.abs(target) < Math.abs(v) || target * v < 0;
    }

    /**
     * Adds one sub-step's true motion to the odometry estimate, as the wheel encoders see it:
     * the distance along the heading and the rotation, each with this run's scale error and
     * random-walk noise, plus the run's heading drift per metre.
     */
    private void deadReckon(double x0, double y0, double yaw0) {
        double dTheta = Angles.normalize(yawRad - yaw0);
        double mid = yaw0 + 0.5 * dTheta;
        double dd = (xM - x0) * StrictMath.cos(mid) + (yM - y0) * StrictMath.sin(mid);
        if (dd == 0 && dTheta == 0) {
            return;
        }
        OdometryError e = model.odometry();
        double ddOdo = dd * distanceScale;
        double dThetaOdo = dTheta * rotationScale + headingDriftRadPerM * dd;
        if (e.distanceNoiseMPerSqrtM() > 0 && dd != 0) {
            ddOdo += e.distanceNoiseMPerSqrtM() * Math.sqrt(Math.abs(dd)) * driftNoise.nextGaussian();
        }
        if (e.rotationNoiseRadPerSqrtRad() > 0 && dTheta != 0) {
            dThetaOdo += e.rotationNoiseRadPerSqrtRad() * Math.sqrt(Math.abs(dTheta)) * driftNoise.nextGaussian();
        }
        double odoMid = odoYawRad + 0.5 * dThetaOdo;
        odoXM += ddOdo * StrictMath.cos(odoMid);
        odoYM += ddOdo * StrictMath.sin(odoMid);
        odoYawRad = Angles.normalize(odoYawRad + dThetaOdo);
    }

    /**
     * Advances a sweeping laser: measures every beam whose time has come from the current
     * pose, delivers a finished scan once its delivery time has come, and starts the next
     * sweep on the laser's period grid.
     */
    private void sweep() {
        int beams = laser.config().beams();
        while (true) {
            if (sweepNextBeam < beams) {
                int to = sweepNextBeam;
                while (to < beams && sweepStartNs + (long) (to * beamIntervalNs) <= timeNs) {
                    to++;
                }
                if (to > sweepNextBeam) {
                    laser.measure(sweepNextBeam, to, xM, yM, yawRad, laserNoise, sweepScan);
                    sweepNextBeam = to;
                }
                if (sweepNextBeam < beams) {
                    return;
                }
                sweepDeliveryNs = sweepStartNs + (long) ((beams - 1) * beamIntervalNs)
                        + model.laserTiming().deliveryDelayNs();
            }
            if (sweepDeliveryNs >= 0) {
                if (sweepDeliveryNs > timeNs) {
                    return;
                }
                laser.finish(timeS(), sweepScan);
                scan.copyFrom(sweepScan);
                scanFirstBeamNs = sweepStartNs;
                scanFresh = true;
                sweepDeliveryNs = -1;
                sweepStartNs = nextDue(sweepStartNs, laserPeriodNs);
                sweepNextBeam = 0;
            }
        }
    }

    private long nextDue(long due, long period) {
        long next = due + period;
        if (next <= timeNs) {
            next = due + ((timeNs - due) / period + 1) * period;
        }
        return next;
    }

    private void integrate(double h) {
        double yaw0 = yawRad;
        double dTheta = omegaRadPerS * h;
        double nx;
        double ny;
        if (Math.abs(dTheta) < 1e-12) {
            nx = xM + vMps * h * StrictMath.cos(yaw0);
            ny = yM + vMps * h * StrictMath.sin(yaw0);
        } else {
            double r = vMps / omegaRadPerS;
            nx = xM + r * (StrictMath.sin(yaw0 + dTheta) - StrictMath.sin(yaw0));
            ny = yM - r * (StrictMath.cos(yaw0 + dTheta) - StrictMath.cos(yaw0));
        }
        yawRad = Angles.normalize(yaw0 + dTheta);
        if (nx == xM && ny == yM) {
            return;
        }
        double radius = robot.radiusM();
        double limit = radius + MAX_SUBSTEP_M;
        double clearNew = clearanceM(nx, ny, limit);
        if (clearNew >= radius) {
            xM = nx;
            yM = ny;
            return;
        }
        double clearOld = clearanceM(xM, yM, limit);
        if (clearNew > clearOld) {
            xM = nx;
            yM = ny;
            return;
        }
        // Blocked: bisect for the furthest free point of the straight sub-step.
        double lo = 0.0;
        double hi = 1.0;
        for (int k = 0; k < BISECTION_STEPS; k++) {
            double mid = 0.5 * (lo + hi);
            double c = clearanceM(xM + (nx - xM) * mid, yM + (ny - yM) * mid, limit);
            if (c >= radius || c > clearOld) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        xM += (nx - xM) * lo;
        yM += (ny - yM) * lo;
        vMps = 0.0;
        stalled = true;
        if (!inContact) {
            inContact = true;
            contactCount++;
        }
    }

    private void placeAt(Pose2d pose) {
        Objects.requireNonNull(pose, "pose");
        if (!Double.isFinite(pose.xM()) || !Double.isFinite(pose.yM()) || !Double.isFinite(pose.yawRad())) {
            throw new IllegalArgumentException("pose must be finite, got " + pose);
        }
        xM = pose.xM();
        yM = pose.yM();
        yawRad = Angles.normalize(pose.yawRad());
        inContact = clearanceM(xM, yM, robot.radiusM() + 2 * CONTACT_RELEASE_M)
                <= robot.radiusM() + CONTACT_RELEASE_M;
    }

    private void publishOdometry() {
        double nx = 0;
        double ny = 0;
        double nyaw = 0;
        if (robot.odometryNoiseM() > 0) {
            nx = robot.odometryNoiseM() * odometryNoise.nextGaussian();
            ny = robot.odometryNoiseM() * odometryNoise.nextGaussian();
        }
        if (robot.odometryNoiseRad() > 0) {
            nyaw = robot.odometryNoiseRad() * odometryNoise.nextGaussian();
        }
        boolean dead = !model.odometry().isNone();
        odometry.xM = (dead ? odoXM : xM) + nx;
        odometry.yM = (dead ? odoYM : yM) + ny;
        odometry.yawRad = Angles.normalize((dead ? odoYawRad : yawRad) + nyaw);
        odometry.vxMps = vMps;
        odometry.vyMps = 0.0;
        odometry.omegaRadPerSec = omegaRadPerS;
        odometry.stall = stalled;
        odometry.serverTimeS = timeS();
        odometryFresh = true;
    }

    private void publishScan() {
        laser.scan(xM, yM, yawRad, timeS(), laserNoise, scan);
        scanFirstBeamNs = timeNs;
        scanFresh = true;
    }

    private static double clamp(double v, double max) {
        return Math.max(-max, Math.min(max, v));
    }

    private static double approach(double v, double target, double maxDelta) {
        double d = target - v;
        if (d > maxDelta) {
            return v + maxDelta;
        }
        if (d < -maxDelta) {
            return v - maxDelta;
        }
        return target;
    }

    /** @return the world map */
    public OccupancyMap map() {
        return map;
    }

    /** @return the robot's parameters */
    public RobotConfig robotConfig() {
        return robot;
    }

    /** @return the laser's parameters */
    public LaserConfig laserConfig() {
        return laser.config();
    }

    /** @return world time since creation in nanoseconds */
    public long timeNs() {
        return timeNs;
    }

    /** @return world time since creation in seconds (the server's timestamps) */
    public double timeS() {
        return timeNs * 1e-9;
    }

    /** @return the ground-truth pose (allocates) */
    public Pose2d pose() {
        return new Pose2d(xM, yM, yawRad);
    }

    /**
     * @return world time in nanoseconds at which the latest scan's first beam was measured: the
     *     start of its sweep for a sweeping laser ({@link LaserTiming#sweep()}), else the instant
     *     of the scan; the scan itself carries its delivery time, as Player stamps it
     */
    public long scanFirstBeamNs() {
        return scanFirstBeamNs;
    }

    /** @return ground-truth x in metres */
    public double xM() {
        return xM;
    }

    /** @return ground-truth y in metres */
    public double yM() {
        return yM;
    }

    /** @return ground-truth heading in radians */
    public double yawRad() {
        return yawRad;
    }

    /** @return actual forward speed in m/s */
    public double speedMps() {
        return vMps;
    }

    /** @return actual turn rate in rad/s */
    public double turnRateRadPerS() {
        return omegaRadPerS;
    }

    /** @return true if the robot's motion was blocked by an obstacle during the last step */
    public boolean stalled() {
        return stalled;
    }

    /** @return the scenario's actors, placed at the last step */
    public Actors actors() {
        return actors;
    }

    /**
     * @return the smallest distance between the robot's body and any obstacle (map or actor)
     *     at the end of any step so far, metres; {@value #CLEARANCE_LIMIT_M} means at least that
     */
    public double minClearanceM() {
        return minClearanceM;
    }

    /**
     * @return approaches within {@value #NEAR_MISS_MARGIN_M} m of an obstacle that did not touch
     *     it, counting one still under way that has not touched
     */
    public long nearMisses() {
        return nearMisses + (nearMissOpen && !nearMissTouched ? 1 : 0);
    }

    /** @return number of contact events so far (one per contact, however long it lasts) */
    public long contactCount() {
        return contactCount;
    }

    /** @return true if the last step (or creation) published new odometry */
    public boolean odometryFresh() {
        return odometryFresh;
    }

    /** @return true if the last step (or creation) published a new scan */
    public boolean scanFresh() {
        return scanFresh;
    }

    /** @return the latest odometry; owned by the world and overwritten by later steps */
    public Odometry odometry() {
        return odometry;
    }

    /** @return the latest scan; owned by the world and overwritten by later steps */
    public LaserScan scan() {
        return scan;
    }
}
