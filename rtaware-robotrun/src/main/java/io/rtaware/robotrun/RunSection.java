package io.rtaware.robotrun;

import java.util.List;
import java.util.Map;

/**
 * The {@code run} section of {@code report.json} (names as in issue 5; more fields may be added).
 *
 * @param scenario the scenario's name
 * @param periodsMs periods of the four behaviors in ms
 * @param outcome {@code completed}, {@code timeout}, {@code stuck}, {@code interrupted} or {@code error}
 * @param completed true if the run is complete as the paper defines it: the robot, by its own
 *     estimate (odometry), passed every waypoint and reached the finish within the time limit
 *     without getting stuck; how near the true pose came is measured separately
 *     ({@code distanceToFinishM}, {@code waypointPasses})
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
 * @param completedMeans the definition of {@code completed}, in words ({@link #COMPLETED_MEANS})
 * @param waypointPasses for each waypoint the robot believed it passed, in order: when, and
 *     how far its true and its believed position were from the waypoint then
 * @param robotModel the simulated robot model's name and parameters ({@code name}: koala or
 *     ideal); for an external Player server {@code name} is {@code external}
 * @param inflationMarginM the clearance the planner added to the robot's radius, metres
 * @param robotSeed the seed of the simulated robot's systematic odometry errors ({@code --robot-seed});
 *     null for an external robot
 * @param robotErrors the systematic errors that robot seed drew ({@code distance_scale_error},
 *     {@code rotation_scale_error}, {@code heading_drift_rad_per_m}); null for an external robot
 * @param minClearanceM the smallest distance between the robot's body and any obstacle, the map's or
 *     an actor's, over the run (measured by the simulator on every step; 0 in a collision; values of
 *     {@code clearance_limit_m} mean at least that); null for an external robot
 * @param nearMisses approaches within {@code nearMissMarginM} of an obstacle that did not touch it; null
 *     for an external robot
 * @param nearMissMarginM the margin of a near miss, metres
 * @param clearanceLimitM clearances beyond this are not measured exactly, metres
 */
public record RunSection(String scenario, Map<String, Double> periodsMs, String outcome, boolean completed,
                         double runTimeS, int waypointsReached, int waypointsTotal, Double distanceToFinishM,
                         double distanceTravelledM, long collisions, Map<String, Long> mediator,
                         String measuredOn, String collisionsFrom, double timeScale, long seed,
                         double gridResolutionM, long staleStops, String reason,
                         List<GroundTruthGap> groundTruthGaps, double groundTruthCoveredS, String completedMeans,
                         List<WaypointPass> waypointPasses, Map<String, Object> robotModel,
                         double inflationMarginM, Long robotSeed, Map<String, Object> robotErrors,
                         Double minClearanceM, Long nearMisses, Double nearMissMarginM, Double clearanceLimitM) {

    /** What {@code completed} means, written into every report. */
    public static final String COMPLETED_MEANS = "the robot, by its own estimate (odometry), passed every waypoint "
            + "and reached the finish within the time limit without getting stuck (the paper's definition); "
            + "distance_to_finish_m and waypoint_passes[].true_distance_m are measured on the true pose";

    /**
     * One waypoint the robot believed it passed.
     *
     * @param index the waypoint's index in the course (the last is the finish)
     * @param tS world seconds from the start
     * @param trueDistanceM distance from the true pose to the waypoint then, metres; null where no
     *     ground truth exists (an external ROS 2 robot, a Player server without {@code simulation:0})
     *     or it was lost then
     * @param believedDistanceM distance from the robot's odometry pose to the waypoint then, metres
     */
    public record WaypointPass(int index, double tS, Double trueDistanceM, double believedDistanceM) {
    }
}
