package io.rtaware.robot.msg;

import io.rtaware.core.data.StateValue;

/**
 * A planned path: points from the robot's position to a goal, in world metres, with the goal
 * it leads to. Fixed capacity, mutable buffer for the data store; {@link #copyFrom} copies
 * without allocating. Not thread-safe.
 */
public final class PlannedPath implements StateValue<PlannedPath> {

    /** Default capacity in points. */
    public static final int DEFAULT_CAPACITY = 4096;

    /** true when a path to a goal was found; false when there is no goal or no way there. */
    public boolean valid;
    /** x of the goal the path leads to, in metres. */
    public double goalXM;
    /** y of the goal the path leads to, in metres. */
    public double goalYM;
    /** id of that goal, as given by its requester. */
    public long goalId;
    /** index of the requester of that goal in the planner's list of requesters. */
    public int requesterIndex;
    /** path cost in metres (unknown cells and cells near obstacles cost more than their length). */
    public double costM;
    /** number of plans made so far by the planner. */
    public long planCount;
    /** x of each point in metres; only the first {@link #count()} are valid. */
    public final double[] xM;
    /** y of each point in metres. */
    public final double[] yM;
    private int count;

    /** A path with {@link #DEFAULT_CAPACITY} points of capacity. */
    public PlannedPath() {
        this(DEFAULT_CAPACITY);
    }

    /** @param capacity maximum number of points */
    public PlannedPath(int capacity) {
        this.xM = new double[capacity];
        this.yM = new double[capacity];
    }

    /** @return number of valid points */
    public int count() {
        return count;
    }

    /** @return the maximum number of points */
    public int capacity() {
        return xM.length;
    }

    /**
     * @param points number of valid points
     * @throws IllegalArgumentException if negative or above the capacity
     */
    public void setCount(int points) {
        if (points < 0 || points > xM.length) {
            throw new IllegalArgumentException("path length " + points + " outside 0.." + xM.length);
        }
        this.count = points;
    }

    /** Marks the path as invalid and empty; keeps the plan count. */
    public void clear() {
        valid = false;
        count = 0;
        costM = 0;
        goalId = 0;
        requesterIndex = -1;
    }

    @Override
    public void copyFrom(PlannedPath s) {
        valid = s.valid;
        goalXM = s.goalXM;
        goalYM = s.goalYM;
        goalId = s.goalId;
        requesterIndex = s.requesterIndex;
        costM = s.costM;
        planCount = s.planCount;
        setCount(s.count);
        System.arraycopy(s.xM, 0, xM, 0, s.count);
        System.arraycopy(s.yM, 0, yM, 0, s.count);
    }
}
