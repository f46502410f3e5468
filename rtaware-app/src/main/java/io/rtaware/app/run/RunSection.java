package io.rtaware.app.run;

import java.util.Map;

/**
 * The {@code run} section of {@code report.json} (names as in issue 5; more fields may be added).
 *
 * @param scenario the scenario's name
 * @param periodsMs periods of the four behaviors in ms
 * @param outcome {@code completed}, {@code timeout}, {@code stuck}, {@code interrupted} or {@code error}
 * @param completed true if every waypoint was reached
 * @param runTimeS world seconds from start to the end of the run (to the finish if completed)
 * @param waypointsReached waypoints reached
 * @param waypointsTotal waypoints in the course
 * @param distanceToFinishM distance from the robot's final position to the finish
 * @param distanceTravelledM length of the path driven
 * @param collisions contacts with obstacles
 * @param mediator cycles won by the obstacle avoider, by the waypoint planner, and stops
 * @param measuredOn {@code ground_truth} (simulation:0) or {@code odometry}
 * @param collisionsFrom {@code simulator} (contact count) or {@code stall} (rising stall edges)
 * @param timeScale world seconds per wall second
 * @param seed the simulator's seed
 * @param gridResolutionM the occupancy grid's resolution
 * @param staleStops stops the mediator commanded because the winning request was too old
 * @param reason why the run ended, in words
 */
public record RunSection(String scenario, Map<String, Double> periodsMs, String outcome, boolean completed,
                         double runTimeS, int waypointsReached, int waypointsTotal, double distanceToFinishM,
                         double distanceTravelledM, long collisions, Map<String, Long> mediator,
                         String measuredOn, String collisionsFrom, double timeScale, long seed,
                         double gridResolutionM, long staleStops, String reason) {
}
