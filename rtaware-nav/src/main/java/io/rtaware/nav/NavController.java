package io.rtaware.nav;

import io.rtaware.core.task.ErrorPolicy;
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
        int w = config.gridWidthCells();
        int h = config.gridHeightCells();

        GoalSet course = new GoalSet(NavConfig.MAX_WAYPOINTS);
        List<Point2d> points = config.waypoints();
        for (int i = 0; i < points.size(); i++) {
            course.add(i + 1, points.get(i).xM(), points.get(i).yM());
        }
        this.waypoint = new WaypointPlannerTask(keys.goalsWaypoint(), keys.path(), keys.course(),
                config.externalWaypoints() ? keys.waypointsIn() : null, course,
                new WaypointSequencer(GoalSet.DEFAULT_CAPACITY, config.goalToleranceM()),
                new PathFollower(config.topSpeedMps(), config.maxOmegaRadPerSec(), config.lookaheadM(),
                        config.turnInPlaceRad()),
                config.odometryMaxAgeNs());
        ObstacleAvoidanceTask obstacle = new ObstacleAvoidanceTask(
                new ObstacleAvoider(config.avoidRangeM(), config.avoidHalfAngleRad(), config.avoidStopRangeM(),
                        config.avoidSpeedMps(), config.maxOmegaRadPerSec()),
                config.laserMaxAgeNs());
        this.occupancy = new OccupancyGridTask(keys.map(),
                new LogOddsGrid(config.gridOriginXM(), config.gridOriginYM(), w, h, config.gridResolutionM()),
                config.laserMaxAgeNs(), config.odometryMaxAgeNs());
        DijkstraPlannerTask planner = new DijkstraPlannerTask(keys.map(), keys.path(), List.of(keys.goalsWaypoint()),
                new DijkstraPlanner(w * h, config.inflationRadiusM(), config.unknownCostFactor()),
                REPLAN_DISTANCE_CELLS * config.gridResolutionM());
        this.mediator = new PositionMediatorTask(config.avoidMaxAgeNs(), config.waypointMaxAgeNs());
        this.specs = List.of(
                spec(NavConfig.WAYPOINT, config.waypointPeriodNs(), waypoint),
                spec(NavConfig.OBSTACLE, config.obstaclePeriodNs(), obstacle),
                spec(NavConfig.OCCUPANCY, config.occupancyPeriodNs(), occupancy),
                spec(NavConfig.PLANNER, config.plannerPeriodNs(), planner),
                spec(NavConfig.MEDIATOR, config.mediatorPeriodNs(), mediator));
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
