package io.rtaware.sim.scenario;

import io.rtaware.robot.geometry.Point2d;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.sim.actor.ActorSpec;
import io.rtaware.sim.map.OccupancyMap;
import io.rtaware.sim.world.RobotModel;
import java.util.List;
import java.util.Objects;
import java.util.Optional;

/**
 * One run's course: where the robot starts, the waypoints it must reach in order (the last
 * one is the finish), how close counts as reached and how long it may take. Poses are in the
 * frame the robot server reports. Immutable and thread-safe.
 *
 * @param name the scenario's name (file name without extension, or the built-in name)
 * @param map the world map; empty when the robot is an external Player server
 * @param start the start pose
 * @param waypoints the waypoints in order, at least one; the last is the finish
 * @param goalToleranceM distance in metres within which a waypoint counts as reached
 * @param timeLimitS the time limit in seconds
 * @param robot the robot model the scenario asks for (its {@code robot:} section); empty for
 *     the default (the Koala at the paper's top speed)
 * @param actors what moves, closes or appears in the world (its {@code actors:} section), at most
 *     {@link #MAX_ACTORS}; empty for a world that stands still
 */
public record Scenario(String name, Optional<OccupancyMap> map, Pose2d start, List<Point2d> waypoints,
                       double goalToleranceM, double timeLimitS, Optional<RobotModel> robot, List<ActorSpec> actors) {

    /**
     * The most actors a scenario may have: every laser beam is cast against each actor present,
     * and the robot's body is measured against each on every step of the world; the built-in
     * scenarios have three at most.
     */
    public static final int MAX_ACTORS = 100;

    /**
     * A scenario without actors.
     *
     * @param name the scenario's name
     * @param map the world map
     * @param start the start pose
     * @param waypoints the waypoints in order
     * @param goalToleranceM waypoint tolerance in metres
     * @param timeLimitS time limit in seconds
     * @param robot the robot model it asks for, or empty
     */
    public Scenario(String name, Optional<OccupancyMap> map, Pose2d start, List<Point2d> waypoints,
                    double goalToleranceM, double timeLimitS, Optional<RobotModel> robot) {
        this(name, map, start, waypoints, goalToleranceM, timeLimitS, robot, List.of());
    }

    /**
     * A scenario without a {@code robot:} section.
     *
     * @param name the scenario's name
     * @param map the world map
     * @param start the start pose
     * @param waypoints the waypoints in order
     * @param goalToleranceM waypoint tolerance in metres
     * @param timeLimitS time limit in seconds
     */
    public Scenario(String name, Optional<OccupancyMap> map, Pose2d start, List<Point2d> waypoints,
                    double goalToleranceM, double timeLimitS) {
        this(name, map, start, waypoints, goalToleranceM, timeLimitS, Optional.empty(), List.of());
    }

    /**
     * @param name the scenario's name
     * @param map the world map
     * @param start the start pose
     * @param waypoints the waypoints in order
     * @param goalToleranceM waypoint tolerance in metres
     * @param timeLimitS time limit in seconds
     * @param robot the robot model the scenario asks for (its {@code robot:} section); empty for the default
     *     (the Koala at the paper's top speed)
     * @param actors what moves, closes or appears in the world; empty for a still world
     * @throws IllegalArgumentException naming the field and value if anything is out of range
     */
    public Scenario {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(map, "map");
        Objects.requireNonNull(start, "start");
        Objects.requireNonNull(robot, "robot");
        if (!Double.isFinite(start.xM()) || !Double.isFinite(start.yM()) || !Double.isFinite(start.yawRad())) {
            throw new IllegalArgumentException("start must be finite, got " + start);
        }
        waypoints = List.copyOf(waypoints);
        actors = List.copyOf(actors);
        if (waypoints.isEmpty()) {
            throw new IllegalArgumentException("waypoints must not be empty, got []");
        }
        if (actors.size() > MAX_ACTORS) {
            throw new IllegalArgumentException("actors must be at most " + MAX_ACTORS + ", got " + actors.size());
        }
        for (Point2d p : waypoints) {
            if (!Double.isFinite(p.xM()) || !Double.isFinite(p.yM())) {
                throw new IllegalArgumentException("waypoints must be finite, got " + p);
            }
        }
        if (!(goalToleranceM > 0) || Double.isInfinite(goalToleranceM)) {
            throw new IllegalArgumentException("goal_tolerance_m must be positive, got " + goalToleranceM);
        }
        if (!(timeLimitS > 0) || Double.isInfinite(timeLimitS)) {
            throw new IllegalArgumentException("time_limit_s must be positive, got " + timeLimitS);
        }
    }

    /**
     * @return the fastest actor's speed, m/s (0 without moving actors): the speed an obstacle
     *     may close on the robot at, besides the robot's own
     */
    public double fastestActorMps() {
        return actors.stream().filter(ActorSpec::moves).mapToDouble(ActorSpec::speedMps).max().orElse(0.0);
    }

    /** @return the last waypoint */
    public Point2d finish() {
        return waypoints.get(waypoints.size() - 1);
    }
}
