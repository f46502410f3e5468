package io.rtaware.nav;

import io.rtaware.core.task.ErrorPolicy;
import io.rtaware.core.task.ReactionConstraint;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.nav.logic.DijkstraPlanner;
import io.rtaware.nav.logic.LogOddsGrid;
import io.rtaware.nav.logic.ObstacleAvoider;
import io.rtaware.nav.logic.PathFollower;
import io.rtaware.nav.logic.WaypointSequencer;
import io.rtaware.nav.task.DijkstraPlannerTask;
import io.rtaware.nav.task.ObstacleAvoidanceTask;
import io.rtaware.nav.task.OccupancyGridTask;
import io.rtaware.nav.task.PositionMediatorTask;
import io.rtaware.nav.task.WaypointPlannerTask;
import io.rtaware.robot.geometry.Point2d;
import io.rtaware.robot.msg.GoalSet;
import io.rtaware.robot.msg.OccupancyGrid;
import io.rtaware.robot.msg.RobotKeys;
import java.util.List;
import java.util.Optional;

/**
 * The paper's waypoint-navigation controller, composed: four behaviors and the position
 * mediator as tasks, ready to register with the monitor. Each instance owns fresh tasks, so its
 * {@link #taskSpecs()} are registered with one monitor, once. The tasks consume
 * {@code laser} and {@code odometry} and produce {@code motor} (see
 * {@link io.rtaware.robot.msg.RobotKeys}), which the Player data task provides and sends.
 *
 * <p>Immutable after construction and thread-safe: {@link #mediatorCounts()},
 * {@link #courseProgress()} and {@link #finalMap()} may be called from any thread while the
 * tasks run.
 */
public final class NavController {

    /** Robot movement that triggers a replan by itself, in grid cells. */
    private static final double REPLAN_DISTANCE_CELLS = 2.0;

    private final NavConfig config;
    private final NavKeys keys;
    private final WaypointPlannerTask waypoint;
    private final OccupancyGridTask occupancy;
    private final PositionMediatorTask mediator;
    private final List<TaskSpec> specs;

    /**
     * Builds the tasks and allocates their working memory (the grid and the planner's arrays:
     * about 30 bytes per cell).
     *
     * @param config the configuration
     */
    public NavController(NavConfig config) {
        this.config = config;
        this.keys = new NavKeys(config);
        NavConfig.Grid grid = config.grid();
        NavConfig.Robot robot = config.robot();
        NavConfig.Avoider avoid = config.avoider();
        NavConfig.MaxAges maxAges = config.maxAges();
        int w = grid.widthCells();
        int h = grid.heightCells();

        GoalSet course = new GoalSet(NavConfig.MAX_WAYPOINTS);
        List<Point2d> points = config.course().waypoints();
        for (int i = 0; i < points.size(); i++) {
            course.add(i + 1, points.get(i).xM(), points.get(i).yM());
        }
        this.waypoint = new WaypointPlannerTask(keys.goalsWaypoint(), keys.path(), keys.course(),
                config.course().external() ? keys.waypointsIn() : null, course,
                new WaypointSequencer(GoalSet.DEFAULT_CAPACITY, config.follower().goalToleranceM()),
                new PathFollower(robot.topSpeedMps(), robot.maxOmegaRadPerSec(), config.follower().lookaheadM(),
                        config.follower().turnInPlaceRad()),
                maxAges.odometryNs());
        ObstacleAvoidanceTask obstacle = new ObstacleAvoidanceTask(
                new ObstacleAvoider(avoid.rangeM(), avoid.halfAngleRad(), avoid.stopRangeM(), avoid.speedMps(),
                        robot.maxOmegaRadPerSec()),
                maxAges.laserNs(), reaction(config));
        this.occupancy = new OccupancyGridTask(keys.map(),
                new LogOddsGrid(grid.originXM(), grid.originYM(), w, h, grid.resolutionM()),
                maxAges.laserNs(), maxAges.odometryNs());
        DijkstraPlannerTask planner = new DijkstraPlannerTask(keys.map(), keys.path(), List.of(keys.goalsWaypoint()),
                new DijkstraPlanner(w * h, config.inflationRadiusM(), config.planner().unknownCostFactor()),
                REPLAN_DISTANCE_CELLS * grid.resolutionM());
        this.mediator = new PositionMediatorTask(maxAges.avoidRequestNs(), maxAges.waypointRequestNs());
        NavConfig.Periods periods = config.periods();
        this.specs = List.of(
                spec(Behavior.WAYPOINT.taskName(), periods.ns(Behavior.WAYPOINT), waypoint),
                spec(Behavior.OBSTACLE.taskName(), periods.ns(Behavior.OBSTACLE), obstacle),
                spec(Behavior.OCCUPANCY.taskName(), periods.ns(Behavior.OCCUPANCY), occupancy),
                spec(Behavior.PLANNER.taskName(), periods.ns(Behavior.PLANNER), planner),
                spec(NavConfig.MEDIATOR, periods.mediatorNs(), mediator));
    }

    /**
     * The avoider's reaction: what it sees at its safety range, minus the clearance that must
     * remain (the robot's radius, since the laser sits at the centre and the body ends a radius
     * ahead; or the laser's minimum range where that is larger, since anything closer is only
     * seen at the minimum range), must be stopped short of, at the robot's top speed (plus the
     * obstacles' own speed where the scenario says they move), with its stopping distance, from
     * scans as old as the laser's delay. Null when the zone does not reach beyond that clearance
     * (nothing to declare).
     */
    private static ReactionConstraint reaction(NavConfig config) {
        NavConfig.Robot robot = config.robot();
        double rangeM = config.avoider().rangeM() - Math.max(robot.radiusM(), robot.laserMinRangeM());
        if (rangeM <= 0) {
            return null;
        }
        return new ReactionConstraint(RobotKeys.LASER.name(), robot.topSpeedMps(), robot.stoppingDistanceM(), rangeM,
                robot.laserDelayNs() / 1e6, robot.obstacleSpeedMps());
    }

    private static TaskSpec spec(String name, long periodNs, io.rtaware.core.task.Task task) {
        return new TaskSpec(name, Schedule.periodic(periodNs), ErrorPolicy.CONTINUE, task);
    }

    /** @return the configuration */
    public NavConfig config() {
        return config;
    }

    /** @return the keys the controller's tasks share, sized for this configuration */
    public NavKeys keys() {
        return keys;
    }

    /**
     * @return the five tasks, named {@code waypoint}, {@code obstacle}, {@code occupancy},
     *     {@code planner}, {@code mediator}, each periodic with its configured period (deadline
     *     = period) and {@link ErrorPolicy#CONTINUE}; register them with one monitor
     */
    public List<TaskSpec> taskSpecs() {
        return specs;
    }

    /** @return who won the mediator's cycles so far (thread-safe) */
    public PositionMediatorTask.MediatorCounts mediatorCounts() {
        return mediator.counts();
    }

    /** @return course progress as of the waypoint planner's last cycle (thread-safe) */
    public WaypointPlannerTask.CourseProgress courseProgress() {
        return waypoint.progress();
    }

    /**
     * @return the occupancy grid the robot built, once the monitor has terminated the tasks;
     *     empty before (thread-safe). Write it with {@link io.rtaware.nav.map.PgmMapWriter}.
     */
    public Optional<OccupancyGrid> finalMap() {
        return occupancy.finalMap();
    }
}
