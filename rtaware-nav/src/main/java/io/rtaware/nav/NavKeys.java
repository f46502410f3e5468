package io.rtaware.nav;

import io.rtaware.core.data.Key;
import io.rtaware.robot.msg.CourseStatus;
import io.rtaware.robot.msg.GoalSet;
import io.rtaware.robot.msg.OccupancyGrid;
import io.rtaware.robot.msg.PlannedPath;
import io.rtaware.robot.msg.RobotKeys;

/**
 * The keys the navigation behaviors share besides {@link RobotKeys}: the map, the path, the
 * goal requests, the course status and the optional waypoint input. The map key's buffers are
 * sized from the configuration's grid, so keys come from an instance made for one
 * configuration; any task that consumes them must use these instances. Immutable and
 * thread-safe.
 */
public final class NavKeys {

    /** Name of the occupancy grid key, produced by {@code occupancy}. */
    public static final String MAP = "map";
    /** Name of the planned path key, produced by {@code planner}. */
    public static final String PATH = "path";
    /** Prefix of the goal request keys: requester {@code r} writes {@code goals.r}. */
    public static final String GOALS_PREFIX = "goals.";
    /** Name of the waypoint planner's goal request key, produced by {@code waypoint}. */
    public static final String GOALS_WAYPOINT = GOALS_PREFIX + "waypoint";
    /** Name of the course status key, produced by {@code waypoint}. */
    public static final String COURSE = "course";
    /** Name of the optional key through which another task replaces the course. */
    public static final String WAYPOINTS_IN = "waypoints";

    private final Key<OccupancyGrid> map;
    private final Key<PlannedPath> path;
    private final Key<GoalSet> goalsWaypoint;
    private final Key<CourseStatus> course;
    private final Key<GoalSet> waypointsIn;

    /**
     * @param config the configuration the map is sized from
     */
    public NavKeys(NavConfig config) {
        int cells = config.grid().widthCells() * config.grid().heightCells();
        this.map = Key.of(MAP, OccupancyGrid.class, () -> new OccupancyGrid(cells));
        this.path = Key.of(PATH, PlannedPath.class, PlannedPath::new);
        this.goalsWaypoint = Key.of(GOALS_WAYPOINT, GoalSet.class, GoalSet::new);
        this.course = Key.of(COURSE, CourseStatus.class, CourseStatus::new);
        this.waypointsIn = Key.of(WAYPOINTS_IN, GoalSet.class, GoalSet::new);
    }

    /** @return the occupancy grid ({@value #MAP}) */
    public Key<OccupancyGrid> map() {
        return map;
    }

    /** @return the planned path ({@value #PATH}) */
    public Key<PlannedPath> path() {
        return path;
    }

    /** @return the waypoint planner's goal requests ({@value #GOALS_WAYPOINT}) */
    public Key<GoalSet> goalsWaypoint() {
        return goalsWaypoint;
    }

    /** @return the course status ({@value #COURSE}) */
    public Key<CourseStatus> course() {
        return course;
    }

    /** @return the optional course input ({@value #WAYPOINTS_IN}), capacity {@link GoalSet#DEFAULT_CAPACITY} */
    public Key<GoalSet> waypointsIn() {
        return waypointsIn;
    }
}
