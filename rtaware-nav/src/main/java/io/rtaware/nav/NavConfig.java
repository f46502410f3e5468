package io.rtaware.nav;

import io.rtaware.robot.geometry.Point2d;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;

/**
 * Everything the navigation controller is configured with. Immutable and thread-safe; every
 * value is validated on construction and a bad one is reported with its field name. Build one
 * with {@link #builder()}; the defaults are the paper's Set 4 periods and the Koala robot.
 *
 * <p>All positions (grid origin, waypoints) are in the odometry frame, the frame the robot
 * reports its pose in.
 *
 * @param waypointPeriodNs period of the {@code waypoint} task in ns (default 100 ms)
 * @param obstaclePeriodNs period of the {@code obstacle} task in ns (default 50 ms)
 * @param occupancyPeriodNs period of the {@code occupancy} task in ns (default 100 ms)
 * @param plannerPeriodNs period of the {@code planner} task in ns (default 100 ms)
 * @param mediatorPeriodNs period of the {@code mediator} task in ns (default: the shorter of
 *     the obstacle and waypoint periods)
 * @param gridResolutionM cell edge of the occupancy grid in metres (default 0.05). Cost on the
 *     paper's 9.6 m x 6.2 m room (NavBench, one loaded 2-core machine): at 0.05 m one 683-beam
 *     scan takes about 0.2-0.35 ms to integrate and a plan across the room 2-5 ms; at the
 *     paper's 0.5 m, about 0.07-0.11 ms and 5-11 us, but the room's gaps then vanish into whole cells
 * @param gridOriginXM x of the grid's lower-left corner in metres (default -10)
 * @param gridOriginYM y of the grid's lower-left corner in metres (default -10)
 * @param gridWidthM extent of the grid along x in metres (default 20)
 * @param gridHeightM extent of the grid along y in metres (default 20)
 * @param robotRadiusM the robot's radius in metres (default 0.2)
 * @param inflationMarginM clearance the planner adds to the robot radius in metres (default 0.05)
 * @param unknownCostFactor cost factor of driving through unknown cells, at least 1 (default 2)
 * @param topSpeedMps top forward speed in m/s (default 0.1)
 * @param maxOmegaRadPerSec turn-rate limit in rad/s (default 0.5)
 * @param lookaheadM pure-pursuit lookahead in metres (default 0.3)
 * @param turnInPlaceRad heading error above which the robot turns in place (default 0.8 rad)
 * @param goalToleranceM how near a waypoint counts as reached, in metres (default 0.25)
 * @param avoidRangeM depth of the avoider's safety zone in metres (default 0.4)
 * @param avoidHalfAngleRad half-width of the safety zone's sector in radians (default 0.6)
 * @param avoidStopRangeM nearer than this the avoider only turns, in metres (default 0.25)
 * @param avoidSpeedMps forward speed while avoiding in m/s (default 0.03)
 * @param laserMaxAgeNs oldest laser scan the avoider and the mapper trust (default 500 ms)
 * @param odometryMaxAgeNs oldest pose the mapper and the waypoint planner trust (default 500 ms)
 * @param avoidMaxAgeNs oldest avoider request the mediator trusts (default 2 obstacle periods
 *     plus one mediator period)
 * @param waypointMaxAgeNs oldest waypoint request the mediator trusts (default 2 waypoint
 *     periods plus one mediator period)
 * @param waypoints the course in order; the last is the finish; at least one
 * @param externalWaypoints true if the waypoint planner also consumes
 *     {@link NavKeys#WAYPOINTS_IN}, through which another task replaces the course (some task
 *     must then produce it)
 */
public record NavConfig(
        long waypointPeriodNs, long obstaclePeriodNs, long occupancyPeriodNs, long plannerPeriodNs,
        long mediatorPeriodNs,
        double gridResolutionM, double gridOriginXM, double gridOriginYM, double gridWidthM, double gridHeightM,
        double robotRadiusM, double inflationMarginM, double unknownCostFactor,
        double topSpeedMps, double maxOmegaRadPerSec, double lookaheadM, double turnInPlaceRad,
        double goalToleranceM,
        double avoidRangeM, double avoidHalfAngleRad, double avoidStopRangeM, double avoidSpeedMps,
        long laserMaxAgeNs, long odometryMaxAgeNs, long avoidMaxAgeNs, long waypointMaxAgeNs,
        List<Point2d> waypoints, boolean externalWaypoints) {

    /** Task name of the waypoint planner. */
    public static final String WAYPOINT = "waypoint";
    /** Task name of the obstacle avoider. */
    public static final String OBSTACLE = "obstacle";
    /** Task name of the occupancy grid mapper. */
    public static final String OCCUPANCY = "occupancy";
    /** Task name of the path planner. */
    public static final String PLANNER = "planner";
    /** Task name of the position mediator. */
    public static final String MEDIATOR = "mediator";
    /**
     * The paper's four behaviors, in the order of its Table I: the tasks whose periods a user
     * sets on the command line and an experiment varies (the mediator follows them).
     */
    public static final List<String> BEHAVIORS = List.of(WAYPOINT, OBSTACLE, OCCUPANCY, PLANNER);
    /** The task names whose periods can be set, in registration order. */
    public static final List<String> TASK_NAMES = List.of(WAYPOINT, OBSTACLE, OCCUPANCY, PLANNER, MEDIATOR);

    /** Largest grid accepted, in cells (about 30 bytes each across the tasks). */
    public static final long MAX_GRID_CELLS = 4_000_000L;
    /** Largest course accepted, in waypoints. */
    public static final int MAX_WAYPOINTS = 64;

    /** Validates every value; see the field descriptions. */
    public NavConfig {
        positive("waypointPeriodNs", waypointPeriodNs);
        positive("obstaclePeriodNs", obstaclePeriodNs);
        positive("occupancyPeriodNs", occupancyPeriodNs);
        positive("plannerPeriodNs", plannerPeriodNs);
        positive("mediatorPeriodNs", mediatorPeriodNs);
        positive("gridResolutionM", gridResolutionM);
        finite("gridOriginXM", gridOriginXM);
        finite("gridOriginYM", gridOriginYM);
        positive("gridWidthM", gridWidthM);
        positive("gridHeightM", gridHeightM);
        if (gridWidthM < gridResolutionM) {
            throw new IllegalArgumentException("gridWidthM must be at least gridResolutionM, got " + gridWidthM);
        }
        if (gridHeightM < gridResolutionM) {
            throw new IllegalArgumentException("gridHeightM must be at least gridResolutionM, got " + gridHeightM);
        }
        long cells = (long) Math.ceil(gridWidthM / gridResolutionM) * (long) Math.ceil(gridHeightM / gridResolutionM);
        if (cells > MAX_GRID_CELLS) {
            throw new IllegalArgumentException("grid of " + gridWidthM + " x " + gridHeightM + " m at "
                    + gridResolutionM + " m has " + cells + " cells, more than " + MAX_GRID_CELLS);
        }
        nonNegative("robotRadiusM", robotRadiusM);
        nonNegative("inflationMarginM", inflationMarginM);
        if (!(unknownCostFactor >= 1) || Double.isInfinite(unknownCostFactor)) {
            throw new IllegalArgumentException("unknownCostFactor must be >= 1, got " + unknownCostFactor);
        }
        positive("topSpeedMps", topSpeedMps);
        positive("maxOmegaRadPerSec", maxOmegaRadPerSec);
        positive("lookaheadM", lookaheadM);
        if (!(turnInPlaceRad > 0 && turnInPlaceRad <= Math.PI)) {
            throw new IllegalArgumentException("turnInPlaceRad must be in (0, pi], got " + turnInPlaceRad);
        }
        positive("goalToleranceM", goalToleranceM);
        positive("avoidRangeM", avoidRangeM);
        positive("avoidHalfAngleRad", avoidHalfAngleRad);
        if (!(avoidStopRangeM >= 0 && avoidStopRangeM <= avoidRangeM)) {
            throw new IllegalArgumentException("avoidStopRangeM must be in 0..avoidRangeM, got " + avoidStopRangeM);
        }
        nonNegative("avoidSpeedMps", avoidSpeedMps);
        if (avoidSpeedMps > topSpeedMps) {
            throw new IllegalArgumentException("avoidSpeedMps must not exceed topSpeedMps, got " + avoidSpeedMps);
        }
        positive("laserMaxAgeNs", laserMaxAgeNs);
        positive("odometryMaxAgeNs", odometryMaxAgeNs);
        positive("avoidMaxAgeNs", avoidMaxAgeNs);
        positive("waypointMaxAgeNs", waypointMaxAgeNs);
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

    /** @return the grid's cells along x */
    public int gridWidthCells() {
        return (int) Math.ceil(gridWidthM / gridResolutionM);
    }

    /** @return the grid's cells along y */
    public int gridHeightCells() {
        return (int) Math.ceil(gridHeightM / gridResolutionM);
    }

    /** @return robot radius plus margin: the planner's obstacle inflation in metres */
    public double inflationRadiusM() {
        return robotRadiusM + inflationMarginM;
    }

    /**
     * @param taskName one of {@link #TASK_NAMES}
     * @return that task's period in ns
     * @throws IllegalArgumentException for another name
     */
    public long periodNs(String taskName) {
        return switch (taskName) {
            case WAYPOINT -> waypointPeriodNs;
            case OBSTACLE -> obstaclePeriodNs;
            case OCCUPANCY -> occupancyPeriodNs;
            case PLANNER -> plannerPeriodNs;
            case MEDIATOR -> mediatorPeriodNs;
            default -> throw new IllegalArgumentException("unknown task '" + taskName + "' (known: "
                    + String.join(", ", TASK_NAMES) + ")");
        };
    }

    /**
     * Collects a configuration. Periods left unset take the paper's Set 4 values; the mediator
     * period and the mediator's maximum ages, if left unset, are derived from the periods when
     * {@link #build()} is called. Not thread-safe.
     */
    public static final class Builder {
        private long waypointPeriodNs = 100_000_000L;
        private long obstaclePeriodNs = 50_000_000L;
        private long occupancyPeriodNs = 100_000_000L;
        private long plannerPeriodNs = 100_000_000L;
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
        }

        /**
         * Sets the periods of some tasks by name, as given on a command line.
         *
         * @param periodsNs task name ({@link #TASK_NAMES}) to period in ns
         * @return this
         * @throws IllegalArgumentException naming an unknown task or a period of 0 or less
         */
        public Builder periodsNs(Map<String, Long> periodsNs) {
            for (Map.Entry<String, Long> e : periodsNs.entrySet()) {
                long p = e.getValue();
                if (p <= 0) {
                    throw new IllegalArgumentException("period of task '" + e.getKey() + "' must be > 0, got " + p);
                }
                switch (e.getKey()) {
                    case WAYPOINT -> waypointPeriodNs = p;
                    case OBSTACLE -> obstaclePeriodNs = p;
                    case OCCUPANCY -> occupancyPeriodNs = p;
                    case PLANNER -> plannerPeriodNs = p;
                    case MEDIATOR -> mediatorPeriodNs = p;
                    default -> throw new IllegalArgumentException("unknown task '" + e.getKey() + "' (known: "
                            + String.join(", ", TASK_NAMES) + ")");
                }
            }
            return this;
        }

        /** @param ns period of the waypoint task @return this */
        public Builder waypointPeriodNs(long ns) {
            waypointPeriodNs = ns;
            return this;
        }

        /** @param ns period of the obstacle task @return this */
        public Builder obstaclePeriodNs(long ns) {
            obstaclePeriodNs = ns;
            return this;
        }

        /** @param ns period of the occupancy task @return this */
        public Builder occupancyPeriodNs(long ns) {
            occupancyPeriodNs = ns;
            return this;
        }

        /** @param ns period of the planner task @return this */
        public Builder plannerPeriodNs(long ns) {
            plannerPeriodNs = ns;
            return this;
        }

        /** @param ns period of the mediator task (0: the shorter of obstacle and waypoint) @return this */
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

        /** @param m cell edge in metres, keeping the extent @return this */
        public Builder gridResolutionM(double m) {
            gridResolutionM = m;
            return this;
        }

        /** @param m robot radius in metres @return this */
        public Builder robotRadiusM(double m) {
            robotRadiusM = m;
            return this;
        }

        /** @param m clearance added to the radius in metres @return this */
        public Builder inflationMarginM(double m) {
            inflationMarginM = m;
            return this;
        }

        /** @param factor cost factor of unknown cells @return this */
        public Builder unknownCostFactor(double factor) {
            unknownCostFactor = factor;
            return this;
        }

        /** @param mps top speed in m/s @return this */
        public Builder topSpeedMps(double mps) {
            topSpeedMps = mps;
            return this;
        }

        /** @param radPerSec turn-rate limit in rad/s @return this */
        public Builder maxOmegaRadPerSec(double radPerSec) {
            maxOmegaRadPerSec = radPerSec;
            return this;
        }

        /** @param m pure-pursuit lookahead in metres @return this */
        public Builder lookaheadM(double m) {
            lookaheadM = m;
            return this;
        }

        /** @param rad heading error that triggers turning in place @return this */
        public Builder turnInPlaceRad(double rad) {
            turnInPlaceRad = rad;
            return this;
        }

        /** @param m waypoint tolerance in metres @return this */
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

        /** @param ns oldest laser scan trusted @return this */
        public Builder laserMaxAgeNs(long ns) {
            laserMaxAgeNs = ns;
            return this;
        }

        /** @param ns oldest pose trusted @return this */
        public Builder odometryMaxAgeNs(long ns) {
            odometryMaxAgeNs = ns;
            return this;
        }

        /** @param ns oldest avoider request the mediator trusts (0: derived) @return this */
        public Builder avoidMaxAgeNs(long ns) {
            avoidMaxAgeNs = ns;
            return this;
        }

        /** @param ns oldest waypoint request the mediator trusts (0: derived) @return this */
        public Builder waypointMaxAgeNs(long ns) {
            waypointMaxAgeNs = ns;
            return this;
        }

        /** @param points the course in order, in the odometry frame @return this */
        public Builder waypoints(List<Point2d> points) {
            waypoints = new ArrayList<>(Objects.requireNonNull(points, "waypoints"));
            return this;
        }

        /** @param enabled whether the course can be replaced through {@link NavKeys#WAYPOINTS_IN} @return this */
        public Builder externalWaypoints(boolean enabled) {
            externalWaypoints = enabled;
            return this;
        }

        /**
         * @return the validated configuration
         * @throws IllegalArgumentException naming the first bad field and its value
         */
        public NavConfig build() {
            long mediator = mediatorPeriodNs > 0 ? mediatorPeriodNs : Math.min(obstaclePeriodNs, waypointPeriodNs);
            long avoidAge = avoidMaxAgeNs > 0 ? avoidMaxAgeNs : 2 * obstaclePeriodNs + mediator;
            long waypointAge = waypointMaxAgeNs > 0 ? waypointMaxAgeNs : 2 * waypointPeriodNs + mediator;
            return new NavConfig(waypointPeriodNs, obstaclePeriodNs, occupancyPeriodNs, plannerPeriodNs, mediator,
                    gridResolutionM, gridOriginXM, gridOriginYM, gridWidthM, gridHeightM,
                    robotRadiusM, inflationMarginM, unknownCostFactor,
                    topSpeedMps, maxOmegaRadPerSec, lookaheadM, turnInPlaceRad, goalToleranceM,
                    avoidRangeM, avoidHalfAngleRad, avoidStopRangeM, avoidSpeedMps,
                    laserMaxAgeNs, odometryMaxAgeNs, avoidAge, waypointAge,
                    waypoints, externalWaypoints);
        }
    }
}
