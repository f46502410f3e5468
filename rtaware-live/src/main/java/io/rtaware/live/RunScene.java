package io.rtaware.live;

import io.rtaware.nav.NavKeys;
import io.rtaware.nav.task.PositionMediatorTask;
import io.rtaware.robot.geometry.Point2d;
import io.rtaware.robot.msg.OccupancyGrid;
import java.util.List;
import java.util.Objects;
import java.util.function.Supplier;

/**
 * What the live view of a robot run draws besides tasks and keys.
 *
 * @param scenario the scenario's name
 * @param world the world's walls and obstacles ({@link OccupancyGrid#OCCUPIED} cells), or null if unknown
 *     (external robot server); not modified after it is given here
 * @param waypoints the course, in order
 * @param keys the navigation keys whose values are drawn (map, path, course)
 * @param mediator the mediator's win counts so far; must be safe to call from any thread
 * @param outcome how the run ended so far, null while it runs; any thread
 */
public record RunScene(String scenario, OccupancyGrid world, List<Point2d> waypoints, NavKeys keys,
                       Supplier<PositionMediatorTask.MediatorCounts> mediator, Supplier<String> outcome) {

    /**
     * Checks and copies.
     *
     * @param scenario the scenario's name
     * @param world the world's walls and obstacles ({@link OccupancyGrid#OCCUPIED} cells), or null if unknown
     *     (external robot server); not modified after it is given here
     * @param waypoints the course, in order
     * @param keys the navigation keys whose values are drawn (map, path, course)
     * @param mediator the mediator's win counts so far; must be safe to call from any thread
     * @param outcome how the run ended so far, null while it runs; any thread
     */
    public RunScene {
        Objects.requireNonNull(scenario, "scenario");
        waypoints = List.copyOf(waypoints);
        Objects.requireNonNull(keys, "keys");
        Objects.requireNonNull(mediator, "mediator");
        Objects.requireNonNull(outcome, "outcome");
    }
}
