package io.rtaware.app.run;

import java.util.List;
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
 * @param distanceToFinishM distance from the robot's final position to the finish; null when the
 *     final pose is stale (ground truth was lost before the end, see {@code groundTruthGaps})
 * @param distanceTravelledM length of the path driven, summed only over the time ground truth
 *     covered ({@code groundTruthCoveredS})
 * @param collisions contacts with obstacles
 * @param mediator cycles won by the obstacle avoider, by the waypoint planner, and stops
 * @param measuredOn {@code ground_truth} (simulation:0) or {@code odometry}
 * @param collisionsFrom {@code simulator} (contact count) or {@code stall} (rising stall edges)
 * @param timeScale world seconds per wall second
 * @param seed the simulator's seed
 * @param gridResolutionM the occupancy grid's resolution
 * @param staleStops stops the mediator commanded because the winning request was too old
 * @param reason why the run ended, in words
 * @param groundTruthGaps spans without ground truth (empty when it never failed)
 * @param groundTruthCoveredS world seconds of the run that ground truth covered (run time minus
 *     the gaps)
 */
public record RunSection(String scenario, Map<String, Double> periodsMs, String outcome, boolean completed,
                         double runTimeS, int waypointsReached, int waypointsTotal, Double distanceToFinishM,
                         double distanceTravelledM, long collisions, Map<String, Long> mediator,
                         String measuredOn, String collisionsFrom, double timeScale, long seed,
                         double gridResolutionM, long staleStops, String reason,
                         List<GroundTruthGap> groundTruthGaps, double groundTruthCoveredS) {
}
