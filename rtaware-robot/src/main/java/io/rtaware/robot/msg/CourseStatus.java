package io.rtaware.robot.msg;

import io.rtaware.core.data.StateValue;

/**
 * Progress along a waypoint course, published by the waypoint planner. Mutable buffer for the
 * data store; not thread-safe.
 */
public final class CourseStatus implements StateValue<CourseStatus> {

    /** waypoints reached so far. */
    public int waypointsReached;
    /** waypoints in the course (the last one is the finish). */
    public int waypointsTotal;
    /** index of the waypoint being driven to; equals the total when done. */
    public int currentIndex;
    /** true once the finish has been reached. */
    public boolean done;
    /** straight-line distance from the robot to the current waypoint in metres (0 when done). */
    public double distanceToGoalM;
    /** straight-line distance from the robot to the finish in metres. */
    public double distanceToFinishM;
    /** x of the current waypoint in metres (the finish when done). */
    public double goalXM;
    /** y of the current waypoint in metres. */
    public double goalYM;
    /** true while the robot's position is known (odometry received). */
    public boolean positionKnown;

    @Override
    public void copyFrom(CourseStatus s) {
        waypointsReached = s.waypointsReached;
        waypointsTotal = s.waypointsTotal;
        currentIndex = s.currentIndex;
        done = s.done;
        distanceToGoalM = s.distanceToGoalM;
        distanceToFinishM = s.distanceToFinishM;
        goalXM = s.goalXM;
        goalYM = s.goalYM;
        positionKnown = s.positionKnown;
    }
}
