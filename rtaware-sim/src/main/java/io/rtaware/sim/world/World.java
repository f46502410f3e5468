package io.rtaware.sim.world;

import io.rtaware.robot.geometry.Angles;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.sim.map.OccupancyMap;
import io.rtaware.sim.map.RayCaster;
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
 * <p>Odometry (pose in the world frame, like Stage with {@code gps} localization, with
 * optional seeded noise) and laser scans are produced at their world-time rates; the step that
 * produced one sets {@link #odometryFresh()} / {@link #scanFresh()}. Both are also produced at
 * time zero. Same seed, same commands and same steps give bit-identical results.
 *
 * <p>Not thread-safe: one thread owns a world (the server's sim thread or a test).
 */
public final class World {

    /** Longest distance travelled in one integration sub-step, metres. */
    public static final double MAX_SUBSTEP_M = 0.005;
    /** Clearance beyond the radius, in metres, at which a contact is over. */
    public static final double CONTACT_RELEASE_M = 0.01;

    private static final int BISECTION_STEPS = 12;
    private static final long ODOMETRY_SEED_SALT = 0x9E3779B97F4A7C15L;

    private final OccupancyMap map;
    private final RobotConfig robot;
    private final Laser laser;
    private final SplittableRandom laserNoise;
    private final SplittableRandom odometryNoise;
    private final Odometry odometry = new Odometry();
    private final LaserScan scan;
    private final long odometryPeriodNs;
    private final long laserPeriodNs;

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
        this.map = Objects.requireNonNull(map, "map");
        this.robot = Objects.requireNonNull(robot, "robot");
        this.laser = new Laser(Objects.requireNonNull(laserConfig, "laserConfig"), new RayCaster(map));
        this.scan = new LaserScan(laserConfig.beams());
        this.laserNoise = new SplittableRandom(seed);
        this.odometryNoise = new SplittableRandom(seed ^ ODOMETRY_SEED_SALT);
        this.odometryPeriodNs = robot.odometryPeriodNs();
        this.laserPeriodNs = laserConfig.periodNs();
        placeAt(start);
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
        this.cmdVMps = clamp(Double.isFinite(vMps) ? vMps : 0.0, robot.maxSpeedMps());
        this.cmdOmegaRadPerS = clamp(Double.isFinite(omegaRadPerS) ? omegaRadPerS : 0.0, robot.maxTurnRateRadPerS());
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
        double targetV = motorsEnabled ? cmdVMps : 0.0;
        double targetW = motorsEnabled ? cmdOmegaRadPerS : 0.0;
        for (int i = 0; i < substeps && dtNs > 0; i++) {
            vMps = approach(vMps, targetV, robot.maxAccelMps2() * h);
            omegaRadPerS = approach(omegaRadPerS, targetW, robot.maxTurnAccelRadPerS2() * h);
            integrate(h);
        }
        if (inContact && map.clearanceM(xM, yM, robot.radiusM() + 2 * CONTACT_RELEASE_M)
                > robot.radiusM() + CONTACT_RELEASE_M) {
            inContact = false;
        }
        timeNs += dtNs;
        if (timeNs >= nextOdometryNs) {
            publishOdometry();
            nextOdometryNs = nextDue(nextOdometryNs, odometryPeriodNs);
        }
        if (timeNs >= nextScanNs) {
            publishScan();
            nextScanNs = nextDue(nextScanNs, laserPeriodNs);
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
        double clearNew = map.clearanceM(nx, ny, limit);
        if (clearNew >= radius) {
            xM = nx;
            yM = ny;
            return;
        }
        double clearOld = map.clearanceM(xM, yM, limit);
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
            double c = map.clearanceM(xM + (nx - xM) * mid, yM + (ny - yM) * mid, limit);
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
        inContact = map.clearanceM(xM, yM, robot.radiusM() + 2 * CONTACT_RELEASE_M)
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
        odometry.xM = xM + nx;
        odometry.yM = yM + ny;
        odometry.yawRad = Angles.normalize(yawRad + nyaw);
        odometry.vxMps = vMps;
        odometry.vyMps = 0.0;
        odometry.omegaRadPerSec = omegaRadPerS;
        odometry.stall = stalled;
        odometry.serverTimeS = timeS();
        odometryFresh = true;
    }

    private void publishScan() {
        laser.scan(xM, yM, yawRad, timeS(), laserNoise, scan);
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
