package io.rtaware.nav;

import io.rtaware.robot.geometry.Point2d;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;

/**
 * Everything the navigation controller is configured with, in small groups: the tasks'
 * periods, the occupancy grid, the planner, the path follower, the avoider, the robot's limits,
 * the freshness limits of the data, and the course. Immutable and thread-safe; every value is
 * validated on construction and a bad one is reported with its field name. Build one with
 * {@link #builder()}; the defaults are the paper's Set 4 periods ({@link Behavior}) and the
 * Koala at 0.1 m/s.
 *
 * <p>All positions (grid origin, waypoints) are in the odometry frame, the frame the robot
 * reports its pose in.
 *
 * @param periods the tasks' periods
 * @param grid the occupancy grid's extent and resolution
 * @param planner the path planner's settings
 * @param follower the waypoint planner's path following
 * @param avoider the obstacle avoider's safety zone
 * @param robot the robot's size, speed and reaction limits
 * @param maxAges how old data may be before a task stops trusting it
 * @param course the waypoints
 */
public record NavConfig(Periods periods, Grid grid, Planner planner, Follower follower, Avoider avoider,
                        Robot robot, MaxAges maxAges, Course course) {

    /** Task name of the position mediator (not a {@link Behavior}: its period follows theirs). */
    public static final String MEDIATOR = "mediator";
    /** The task names whose periods can be set, in registration order: the behaviors, then the mediator. */
    public static final List<String> TASK_NAMES = taskNames();

    /** Largest grid accepted, in cells (about 30 bytes each across the tasks). */
    public static final long MAX_GRID_CELLS = 4_000_000L;
    /** Largest course accepted, in waypoints. */
    public static final int MAX_WAYPOINTS = 64;

    private static List<String> taskNames() {
        List<String> names = new ArrayList<>(Behavior.taskNames());
        names.add(MEDIATOR);
        return List.copyOf(names);
    }

    /**
     * Validates that no group is missing; each group validates its own values.
     *
     * @param periods the tasks' periods
     * @param grid the occupancy grid's extent and resolution
     * @param planner the path planner's settings
     * @param follower the waypoint planner's path following
     * @param avoider the obstacle avoider's safety zone
     * @param robot the robot's size, speed and reaction limits
     * @param maxAges how old data may be before a task stops trusting it
     * @param course the waypoints
     */
    public NavConfig {
        Objects.requireNonNull(periods, "periods");
        Objects.requireNonNull(grid, "grid");
        Objects.requireNonNull(planner, "planner");
        Objects.requireNonNull(follower, "follower");
        Objects.requireNonNull(avoider, "avoider");
        Objects.requireNonNull(robot, "robot");
        Objects.requireNonNull(maxAges, "maxAges");
        Objects.requireNonNull(course, "course");
        if (avoider.speedMps() > robot.topSpeedMps()) {
            throw new IllegalArgumentException("avoidSpeedMps must not exceed topSpeedMps, got " + avoider.speedMps());
        }
    }

    /**
     * The tasks' periods.
     *
     * @param behaviorsNs each behavior's period in ns
     * @param mediatorNs the mediator's period in ns
     */
    public record Periods(Map<Behavior, Long> behaviorsNs, long mediatorNs) {
        /**
         * @param behaviorsNs each behavior's period in ns
         * @param mediatorNs the mediator's period in ns
         * @throws IllegalArgumentException naming a missing or non-positive period
         */
        public Periods {
            behaviorsNs = Map.copyOf(behaviorsNs);
            for (Behavior b : Behavior.values()) {
                Long p = behaviorsNs.get(b);
                if (p == null) {
                    throw new IllegalArgumentException("period of task '" + b.taskName() + "' is missing");
                }
                positive(b.taskName() + "PeriodNs", p);
            }
            positive("mediatorPeriodNs", mediatorNs);
        }

        /**
         * @param behavior a behavior
         * @return its period in ns
         */
        public long ns(Behavior behavior) {
            return behaviorsNs.get(behavior);
        }
    }

    /**
     * The occupancy grid.
     *
     * @param resolutionM cell edge in metres (default 0.05). Cost on the paper's 9.6 m x 6.2 m
     *     room (NavBench, one loaded 2-core machine): at 0.05 m one 683-beam scan takes about
     *     0.2-0.35 ms to integrate and a plan across the room 2-5 ms; at the paper's 0.5 m, about
     *     0.07-0.11 ms and 5-11 us, but the room's gaps then vanish into whole cells
     * @param originXM x of the lower-left corner in metres (default -10)
     * @param originYM y of the lower-left corner in metres (default -10)
     * @param widthM extent along x in metres (default 20)
     * @param heightM extent along y in metres (default 20)
     */
    public record Grid(double resolutionM, double originXM, double originYM, double widthM, double heightM) {
        /**
         * @param resolutionM cell edge in metres (default 0.05).
         * @param originXM x of the lower-left corner in metres (default -10)
         * @param originYM y of the lower-left corner in metres (default -10)
         * @param widthM extent along x in metres (default 20)
         * @param heightM extent along y in metres (default 20)
         * @throws IllegalArgumentException naming the bad value
         */
        public Grid {
            positive("gridResolutionM", resolutionM);
            finite("gridOriginXM", originXM);
            finite("gridOriginYM", originYM);
            positive("gridWidthM", widthM);
            positive("gridHeightM", heightM);
            if (widthM < resolutionM) {
                throw new IllegalArgumentException("gridWidthM must be at least gridResolutionM, got " + widthM);
            }
            if (heightM < resolutionM) {
                throw new IllegalArgumentException("gridHeightM must be at least gridResolutionM, got " + heightM);
            }
            // In doubles: a hostile configuration (a recording's nav_config) overflowed the product of longs.
            double cells = Math.ceil(widthM / resolutionM) * Math.ceil(heightM / resolutionM);
            if (!(cells <= MAX_GRID_CELLS)) {
                throw new IllegalArgumentException("grid of " + widthM + " x " + heightM + " m at "
                        + resolutionM + " m has " + String.format(java.util.Locale.ROOT, "%.0f", cells)
                        + " cells, more than " + MAX_GRID_CELLS);
            }
        }

        /** @return cells along x */
        public int widthCells() {
            return (int) Math.ceil(widthM / resolutionM);
        }

        /** @return cells along y */
        public int heightCells() {
            return (int) Math.ceil(heightM / resolutionM);
        }
    }

    /**
     * The path planner.
     *
     * @param inflationMarginM clearance added to the robot radius in metres (default 0.05)
     * @param unknownCostFactor cost factor of driving through unknown cells, at least 1 (default 2)
     */
    public record Planner(double inflationMarginM, double unknownCostFactor) {
        /**
         * @param inflationMarginM clearance added to the robot radius in metres (default 0.05)
         * @param unknownCostFactor cost factor of driving through unknown cells, at least 1 (default 2)
         * @throws IllegalArgumentException naming the bad value
         */
        public Planner {
            nonNegative("inflationMarginM", inflationMarginM);
            if (!(unknownCostFactor >= 1) || Double.isInfinite(unknownCostFactor)) {
                throw new IllegalArgumentException("unknownCostFactor must be >= 1, got " + unknownCostFactor);
            }
        }
    }

    /**
     * The waypoint planner's path following.
     *
     * @param lookaheadM pure-pursuit lookahead in metres (default 0.3)
     * @param turnInPlaceRad heading error above which the robot turns in place (default 0.8 rad)
     * @param goalToleranceM how near a waypoint counts as reached, in metres (default 0.25)
     */
    public record Follower(double lookaheadM, double turnInPlaceRad, double goalToleranceM) {
        /**
         * @param lookaheadM pure-pursuit lookahead in metres (default 0.3)
         * @param turnInPlaceRad heading error above which the robot turns in place (default 0.8 rad)
         * @param goalToleranceM how near a waypoint counts as reached, in metres (default 0.25)
         * @throws IllegalArgumentException naming the bad value
         */
        public Follower {
            positive("lookaheadM", lookaheadM);
            if (!(turnInPlaceRad > 0 && turnInPlaceRad <= Math.PI)) {
                throw new IllegalArgumentException("turnInPlaceRad must be in (0, pi], got " + turnInPlaceRad);
            }
            positive("goalToleranceM", goalToleranceM);
        }
    }

    /**
     * The obstacle avoider's safety zone.
     *
     * @param rangeM depth of the safety zone in metres, from the laser (default 0.4)
     * @param halfAngleRad half-width of the zone's sector in radians (default 0.6)
     * @param stopRangeM nearer than this the avoider only turns, in metres (default 0.25)
     * @param speedMps forward speed while avoiding in m/s (default 0.03)
     */
    public record Avoider(double rangeM, double halfAngleRad, double stopRangeM, double speedMps) {
        /**
         * @param rangeM depth of the safety zone in metres, from the laser (default 0.4)
         * @param halfAngleRad half-width of the zone's sector in radians (default 0.6)
         * @param stopRangeM nearer than this the avoider only turns, in metres (default 0.25)
         * @param speedMps forward speed while avoiding in m/s (default 0.03)
         * @throws IllegalArgumentException naming the bad value
         */
        public Avoider {
            positive("avoidRangeM", rangeM);
            positive("avoidHalfAngleRad", halfAngleRad);
            if (!(stopRangeM >= 0 && stopRangeM <= rangeM)) {
                throw new IllegalArgumentException("avoidStopRangeM must be in 0..avoidRangeM, got " + stopRangeM);
            }
            nonNegative("avoidSpeedMps", speedMps);
        }
    }

    /**
     * The robot's size, speed and reaction limits.
     *
     * @param radiusM the robot's radius in metres (default 0.2)
     * @param topSpeedMps top forward speed in m/s (default 0.1)
     * @param maxOmegaRadPerSec turn-rate limit in rad/s (default 0.5)
     * @param stoppingDistanceM distance the robot covers from a stop command at top speed until
     *     it stands, in metres (command latency plus braking; default 0.01, braking at 0.5 m/s^2)
     * @param laserDelayNs age of a laser scan when it is delivered, ns (sweep and transfer;
     *     default 0, an instantaneous laser)
     * @param laserMinRangeM the laser's minimum range in metres: something closer is seen at it
     *     (default 0); the reaction rule keeps at least this much clearance
     * @param obstacleSpeedMps how fast obstacles may move toward the robot, m/s (default 0: they
     *     stand still); the avoider's reaction rule closes the gap at the sum of both speeds
     */
    public record Robot(double radiusM, double topSpeedMps, double maxOmegaRadPerSec, double stoppingDistanceM,
                        long laserDelayNs, double laserMinRangeM, double obstacleSpeedMps) {
        /**
         * @param radiusM the robot's radius in metres (default 0.2)
         * @param topSpeedMps top forward speed in m/s (default 0.1)
         * @param maxOmegaRadPerSec turn-rate limit in rad/s (default 0.5)
         * @param stoppingDistanceM distance the robot covers from a stop command at top speed until it stands,
         *     in metres (command latency plus braking; default 0.01, braking at 0.5 m/s^2)
         * @param laserDelayNs age of a laser scan when it is delivered, ns (sweep and transfer; default 0, an
         *     instantaneous laser)
         * @param laserMinRangeM the laser's minimum range in metres (default 0)
         * @param obstacleSpeedMps how fast obstacles may move toward the robot, m/s (default 0)
         * @throws IllegalArgumentException naming the bad value
         */
        public Robot {
            nonNegative("robotRadiusM", radiusM);
            positive("topSpeedMps", topSpeedMps);
            positive("maxOmegaRadPerSec", maxOmegaRadPerSec);
            nonNegative("stoppingDistanceM", stoppingDistanceM);
            if (laserDelayNs < 0) {
                throw new IllegalArgumentException("laserDelayNs must be >= 0, got " + laserDelayNs);
            }
            nonNegative("laserMinRangeM", laserMinRangeM);
            nonNegative("obstacleSpeedMps", obstacleSpeedMps);
        }
    }

    /**
     * How old data may be before a task stops trusting it.
     *
     * @param laserNs oldest laser scan the avoider and the mapper trust (default 500 ms)
     * @param odometryNs oldest pose the mapper and the waypoint planner trust (default 500 ms)
     * @param avoidRequestNs oldest avoider request the mediator trusts (default 2 obstacle
     *     periods plus one mediator period)
     * @param waypointRequestNs oldest waypoint request the mediator trusts (default 2 waypoint
     *     periods plus one mediator period)
     */
    public record MaxAges(long laserNs, long odometryNs, long avoidRequestNs, long waypointRequestNs) {
        /**
         * @param laserNs oldest laser scan the avoider and the mapper trust (default 500 ms)
         * @param odometryNs oldest pose the mapper and the waypoint planner trust (default 500 ms)
         * @param avoidRequestNs oldest avoider request the mediator trusts (default 2 obstacle periods plus one
         *     mediator period)
         * @param waypointRequestNs oldest waypoint request the mediator trusts (default 2 waypoint periods plus
         *     one mediator period)
         * @throws IllegalArgumentException naming the bad value
         */
        public MaxAges {
            positive("laserMaxAgeNs", laserNs);
            positive("odometryMaxAgeNs", odometryNs);
            positive("avoidMaxAgeNs", avoidRequestNs);
            positive("waypointMaxAgeNs", waypointRequestNs);
        }
    }

    /**
     * The course.
     *
     * @param waypoints the course in order; the last is the finish; 1..{@value #MAX_WAYPOINTS}
     * @param external true if the waypoint planner also consumes {@link NavKeys#WAYPOINTS_IN},
     *     through which another task replaces the course (some task must then produce it)
     */
    public record Course(List<Point2d> waypoints, boolean external) {
        /**
         * @param waypoints the course in order; the last is the finish; 1..{@value #MAX_WAYPOINTS}
         * @param external true if the waypoint planner also consumes {@link NavKeys#WAYPOINTS_IN}, through
         *     which another task replaces the course (some task must then produce it)
         * @throws IllegalArgumentException naming the bad value
         */
        public Course {
            Objects.requireNonNull(waypoints, "waypoints");
            if (waypoints.isEmpty() || waypoints.size() > MAX_WAYPOINTS) {
                throw new IllegalArgumentException("waypoints must hold 1.." + MAX_WAYPOINTS + " points, got "
                        + waypoints.size());
            }
            for (int i = 0; i < waypoints.size(); i++) {
                Point2d p = waypoints.get(i);
                if (p == null || !Double.isFinite(p.xM()) || !Double.isFinite(p.yM())) {
                    throw new IllegalArgumentException("waypoints[" + i + "] must be a finite point, got " + p);
                }
            }
            waypoints = List.copyOf(waypoints);
        }
    }

    private static void positive(String name, long v) {
        if (v <= 0) {
            throw new IllegalArgumentException(name + " must be > 0, got " + v);
        }
    }

    private static void positive(String name, double v) {
        if (!(v > 0) || Double.isInfinite(v)) {
            throw new IllegalArgumentException(name + " must be > 0, got " + v);
        }
    }

    private static void nonNegative(String name, double v) {
        if (!(v >= 0) || Double.isInfinite(v)) {
            throw new IllegalArgumentException(name + " must be >= 0, got " + v);
        }
    }

    private static void finite(String name, double v) {
        if (!Double.isFinite(v)) {
            throw new IllegalArgumentException(name + " must be finite, got " + v);
        }
    }

    /** @return a builder holding the defaults */
    public static Builder builder() {
        return new Builder();
    }

    /** @return robot radius plus margin: the planner's obstacle inflation in metres */
    public double inflationRadiusM() {
        return robot.radiusM() + planner.inflationMarginM();
    }

    /**
     * @param taskName one of {@link #TASK_NAMES}
     * @return that task's period in ns
     * @throws IllegalArgumentException for another name
     */
    public long periodNs(String taskName) {
        return MEDIATOR.equals(taskName) ? periods.mediatorNs() : periods.ns(Behavior.ofTaskName(taskName));
    }

    /**
     * Collects a configuration. Periods left unset take their {@link Behavior}'s default (the
     * paper's Set 4); the mediator period and the mediator's maximum ages, if left unset, are
     * derived from the periods when {@link #build()} is called. Not thread-safe.
     */
    public static final class Builder {
        private final Map<Behavior, Long> periodsNs = new EnumMap<>(Behavior.class);
        private long mediatorPeriodNs;
        private double gridResolutionM = 0.05;
        private double gridOriginXM = -10;
        private double gridOriginYM = -10;
        private double gridWidthM = 20;
        private double gridHeightM = 20;
        private double robotRadiusM = 0.2;
        private double inflationMarginM = 0.05;
        private double unknownCostFactor = 2.0;
        private double topSpeedMps = 0.1;
        private double maxOmegaRadPerSec = 0.5;
        private double stoppingDistanceM = 0.01;
        private long laserDelayNs;
        private double laserMinRangeM;
        private double obstacleSpeedMps;
        private double lookaheadM = 0.3;
        private double turnInPlaceRad = 0.8;
        private double goalToleranceM = 0.25;
        private double avoidRangeM = 0.4;
        private double avoidHalfAngleRad = 0.6;
        private double avoidStopRangeM = 0.25;
        private double avoidSpeedMps = 0.03;
        private long laserMaxAgeNs = 500_000_000L;
        private long odometryMaxAgeNs = 500_000_000L;
        private long avoidMaxAgeNs;
        private long waypointMaxAgeNs;
        private List<Point2d> waypoints = new ArrayList<>();
        private boolean externalWaypoints;

        private Builder() {
            for (Behavior b : Behavior.values()) {
                periodsNs.put(b, b.defaultPeriodNs());
            }
        }

        /**
         * Sets the periods of some tasks by name, as given on a command line.
         *
         * @param byTaskNs task name ({@link #TASK_NAMES}) to period in ns
         * @return this
         * @throws IllegalArgumentException naming an unknown task or a period of 0 or less
         */
        public Builder periodsNs(Map<String, Long> byTaskNs) {
            for (Map.Entry<String, Long> e : byTaskNs.entrySet()) {
                long p = e.getValue();
                if (p <= 0) {
                    throw new IllegalArgumentException("period of task '" + e.getKey() + "' must be > 0, got " + p);
                }
                if (MEDIATOR.equals(e.getKey())) {
                    mediatorPeriodNs = p;
                } else {
                    periodsNs.put(Behavior.ofTaskName(e.getKey()), p);
                }
            }
            return this;
        }

        /**
         * @param behavior a behavior
         * @param ns its period
         * @return this
         */
        public Builder periodNs(Behavior behavior, long ns) {
            periodsNs.put(behavior, ns);
            return this;
        }

        /**

         * @param ns period of the mediator task (0: the shorter of obstacle and waypoint)

         * @return this

         */
        public Builder mediatorPeriodNs(long ns) {
            mediatorPeriodNs = ns;
            return this;
        }

        /**
         * @param resolutionM cell edge in metres
         * @param originXM x of the lower-left corner in metres
         * @param originYM y of the lower-left corner in metres
         * @param widthM extent along x in metres
         * @param heightM extent along y in metres
         * @return this
         */
        public Builder grid(double resolutionM, double originXM, double originYM, double widthM, double heightM) {
            gridResolutionM = resolutionM;
            gridOriginXM = originXM;
            gridOriginYM = originYM;
            gridWidthM = widthM;
            gridHeightM = heightM;
            return this;
        }

        /**

         * @param m cell edge in metres, keeping the extent

         * @return this

         */
        public Builder gridResolutionM(double m) {
            gridResolutionM = m;
            return this;
        }

        /**

         * @param m robot radius in metres

         * @return this

         */
        public Builder robotRadiusM(double m) {
            robotRadiusM = m;
            return this;
        }

        /**

         * @param m clearance added to the radius in metres

         * @return this

         */
        public Builder inflationMarginM(double m) {
            inflationMarginM = m;
            return this;
        }

        /**

         * @param factor cost factor of unknown cells

         * @return this

         */
        public Builder unknownCostFactor(double factor) {
            unknownCostFactor = factor;
            return this;
        }

        /**

         * @param mps top speed in m/s

         * @return this

         */
        public Builder topSpeedMps(double mps) {
            topSpeedMps = mps;
            return this;
        }

        /**

         * @param radPerSec turn-rate limit in rad/s

         * @return this

         */
        public Builder maxOmegaRadPerSec(double radPerSec) {
            maxOmegaRadPerSec = radPerSec;
            return this;
        }

        /**
         * @param stoppingM distance from a stop command at top speed to standing, metres
         * @param laserAgeNs age of a scan when delivered, ns
         * @return this
         */
        public Builder reactionLimits(double stoppingM, long laserAgeNs) {
            stoppingDistanceM = stoppingM;
            laserDelayNs = laserAgeNs;
            return this;
        }

        /**
         * @param m the laser's minimum range in metres
         * @return this
         */
        public Builder laserMinRangeM(double m) {
            laserMinRangeM = m;
            return this;
        }

        /**
         * @param mps how fast obstacles may move toward the robot (a scenario's fastest actor), m/s
         * @return this
         */
        public Builder obstacleSpeedMps(double mps) {
            obstacleSpeedMps = mps;
            return this;
        }

        /**
         * @param m pure-pursuit lookahead in metres
         * @return this
         */
        public Builder lookaheadM(double m) {
            lookaheadM = m;
            return this;
        }

        /**

         * @param rad heading error that triggers turning in place

         * @return this

         */
        public Builder turnInPlaceRad(double rad) {
            turnInPlaceRad = rad;
            return this;
        }

        /**

         * @param m waypoint tolerance in metres

         * @return this

         */
        public Builder goalToleranceM(double m) {
            goalToleranceM = m;
            return this;
        }

        /**
         * @param rangeM depth of the safety zone in metres
         * @param halfAngleRad half-width of its sector in radians
         * @param stopRangeM range below which the avoider only turns, in metres
         * @param speedMps forward speed while avoiding in m/s
         * @return this
         */
        public Builder avoidance(double rangeM, double halfAngleRad, double stopRangeM, double speedMps) {
            avoidRangeM = rangeM;
            avoidHalfAngleRad = halfAngleRad;
            avoidStopRangeM = stopRangeM;
            avoidSpeedMps = speedMps;
            return this;
        }

        /**

         * @param ns oldest laser scan trusted

         * @return this

         */
        public Builder laserMaxAgeNs(long ns) {
            laserMaxAgeNs = ns;
            return this;
        }

        /**

         * @param ns oldest pose trusted

         * @return this

         */
        public Builder odometryMaxAgeNs(long ns) {
            odometryMaxAgeNs = ns;
            return this;
        }

        /**

         * @param ns oldest avoider request the mediator trusts (0: derived)

         * @return this

         */
        public Builder avoidMaxAgeNs(long ns) {
            avoidMaxAgeNs = ns;
            return this;
        }

        /**

         * @param ns oldest waypoint request the mediator trusts (0: derived)

         * @return this

         */
        public Builder waypointMaxAgeNs(long ns) {
            waypointMaxAgeNs = ns;
            return this;
        }

        /**

         * @param points the course in order, in the odometry frame

         * @return this

         */
        public Builder waypoints(List<Point2d> points) {
            waypoints = new ArrayList<>(Objects.requireNonNull(points, "waypoints"));
            return this;
        }

        /**

         * @param enabled whether the course can be replaced through {@link NavKeys#WAYPOINTS_IN}

         * @return this

         */
        public Builder externalWaypoints(boolean enabled) {
            externalWaypoints = enabled;
            return this;
        }

        /**
         * @return the validated configuration
         * @throws IllegalArgumentException naming the first bad field and its value
         */
        public NavConfig build() {
            long obstacle = periodsNs.get(Behavior.OBSTACLE);
            long waypoint = periodsNs.get(Behavior.WAYPOINT);
            long mediator = mediatorPeriodNs > 0 ? mediatorPeriodNs : Math.min(obstacle, waypoint);
            long avoidAge = avoidMaxAgeNs > 0 ? avoidMaxAgeNs : saturatedSum(obstacle, obstacle, mediator);
            long waypointAge = waypointMaxAgeNs > 0 ? waypointMaxAgeNs : saturatedSum(waypoint, waypoint, mediator);
            return new NavConfig(new Periods(periodsNs, mediator),
                    new Grid(gridResolutionM, gridOriginXM, gridOriginYM, gridWidthM, gridHeightM),
                    new Planner(inflationMarginM, unknownCostFactor),
                    new Follower(lookaheadM, turnInPlaceRad, goalToleranceM),
                    new Avoider(avoidRangeM, avoidHalfAngleRad, avoidStopRangeM, avoidSpeedMps),
                    new Robot(robotRadiusM, topSpeedMps, maxOmegaRadPerSec, stoppingDistanceM, laserDelayNs,
                            laserMinRangeM, obstacleSpeedMps),
                    new MaxAges(laserMaxAgeNs, odometryMaxAgeNs, avoidAge, waypointAge),
                    new Course(waypoints, externalWaypoints));
        }

        /** @return the sum of non-negative spans, or Long.MAX_VALUE where it would overflow */
        private static long saturatedSum(long... ns) {
            long sum = 0;
            for (long v : ns) {
                sum = v > Long.MAX_VALUE - sum ? Long.MAX_VALUE : sum + v;
            }
            return sum;
        }
    }
}
