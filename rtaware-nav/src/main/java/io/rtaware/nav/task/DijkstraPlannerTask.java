package io.rtaware.nav.task;

import io.rtaware.core.data.Input;
import io.rtaware.core.data.Key;
import io.rtaware.core.data.Output;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.nav.logic.DijkstraPlanner;
import io.rtaware.nav.logic.GoalRegistry;
import io.rtaware.robot.msg.GoalSet;
import io.rtaware.robot.msg.OccupancyGrid;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.robot.msg.PlannedPath;
import io.rtaware.robot.msg.RobotKeys;
import java.util.ArrayList;
import java.util.List;

/**
 * DijkstraPathPlanner ({@code planner}): consumes {@code map}, {@code odometry} and one goal
 * request key per requester (requester {@code i} is the {@code i}-th key; each key holds that
 * requester's current goals, so a requester adds a goal by writing it and removes it by writing
 * the set without it). Publishes on {@code path} the path from the robot to the closest goal,
 * replanning when the map or the goals change, or when the robot has moved more than
 * {@code replanDistanceM} since the last plan. With no goal it publishes an invalid, empty path.
 *
 * <p>Run by one thread at a time; not otherwise thread-safe.
 */
public final class DijkstraPlannerTask implements Task {

    private final Key<OccupancyGrid> mapKey;
    private final Key<PlannedPath> pathKey;
    private final List<Key<GoalSet>> goalKeys;
    private final DijkstraPlanner planner;
    private final GoalRegistry goals;
    private final double replanDistanceM;
    private Input<OccupancyGrid> map;
    private Input<Odometry> odometry;
    private final List<Input<GoalSet>> goalInputs = new ArrayList<>();
    private Output<PlannedPath> path;
    private boolean dirty;
    private double plannedFromXM;
    private double plannedFromYM;
    private long planCount;

    /**
     * @param mapKey the map key
     * @param pathKey the path key to publish on
     * @param goalKeys one goal request key per requester, in requester order
     * @param planner the planning logic, sized for the map
     * @param replanDistanceM robot movement in metres that triggers a replan by itself
     */
    public DijkstraPlannerTask(Key<OccupancyGrid> mapKey, Key<PlannedPath> pathKey, List<Key<GoalSet>> goalKeys,
                               DijkstraPlanner planner, double replanDistanceM) {
        this.mapKey = mapKey;
        this.pathKey = pathKey;
        this.goalKeys = List.copyOf(goalKeys);
        this.planner = planner;
        this.goals = new GoalRegistry(this.goalKeys.size(), this.goalKeys.size() * GoalSet.DEFAULT_CAPACITY);
        this.replanDistanceM = replanDistanceM;
    }

    @Override
    public void initialize(TaskSetup setup) {
        map = setup.consume(mapKey);
        odometry = setup.consume(RobotKeys.ODOMETRY);
        for (Key<GoalSet> key : goalKeys) {
            goalInputs.add(setup.consume(key));
        }
        path = setup.produce(pathKey);
    }

    @Override
    public void execute(long nowNs) {
        for (int i = 0; i < goalInputs.size(); i++) {
            Input<GoalSet> in = goalInputs.get(i);
            if (in.isNew()) {
                dirty |= goals.replace(i, in.value());
            }
        }
        if (map.isNew()) {
            planner.setMap(map.value());
            dirty = true;
        }
        if (!odometry.hasValue()) {
            return;
        }
        Odometry pose = odometry.value();
        if (!dirty && Math.hypot(pose.xM - plannedFromXM, pose.yM - plannedFromYM) < replanDistanceM) {
            return;
        }
        PlannedPath out = path.value();
        planner.plan(pose.xM, pose.yM, goals, out);
        out.planCount = ++planCount;
        plannedFromXM = pose.xM;
        plannedFromYM = pose.yM;
        dirty = false;
        path.publish();
    }
}
