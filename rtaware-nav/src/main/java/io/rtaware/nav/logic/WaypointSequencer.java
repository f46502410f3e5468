package io.rtaware.nav.logic;

import io.rtaware.robot.msg.GoalSet;

/**
 * An ordered waypoint course: the current waypoint, progress, and the rule that a waypoint is
 * reached when the robot comes within {@code toleranceM} of it; the last waypoint is the
 * finish, and reaching it completes the course. Replacing the waypoints restarts the course
 * and changes the goal ids (each id encodes the course version and the waypoint's index).
 *
 * <p>Fixed capacity; not thread-safe; allocates nothing after construction.
 */
public final class WaypointSequencer {

    private static final long VERSION_STRIDE = 1L << 32;

    private final double toleranceM;
    private final double[] xM;
    private final double[] yM;
    private int count;
    private int index;
    private long version;

    /**
     * @param capacity maximum number of waypoints
     * @param toleranceM how near counts as reached, in metres
     * @throws IllegalArgumentException naming the bad value
     */
    public WaypointSequencer(int capacity, double toleranceM) {
        if (capacity <= 0) {
            throw new IllegalArgumentException("capacity must be > 0, got " + capacity);
        }
        if (!(toleranceM > 0) || Double.isInfinite(toleranceM)) {
            throw new IllegalArgumentException("toleranceM must be > 0, got " + toleranceM);
        }
        this.toleranceM = toleranceM;
        this.xM = new double[capacity];
        this.yM = new double[capacity];
    }

    /**
     * Replaces the course; progress restarts at the first waypoint.
     *
     * @param waypoints the waypoints in order (ids are ignored)
     * @throws IllegalArgumentException if there are more than the capacity
     */
    public void setWaypoints(GoalSet waypoints) {
        if (waypoints.count() > xM.length) {
            throw new IllegalArgumentException(waypoints.count() + " waypoints exceed capacity " + xM.length);
        }
        for (int i = 0; i < waypoints.count(); i++) {
            xM[i] = waypoints.xM[i];
            yM[i] = waypoints.yM[i];
        }
        count = waypoints.count();
        index = 0;
        version++;
    }

    /**
     * Checks whether the robot reached the current waypoint and, if so, moves on to the next.
     *
     * @param robotXM robot x in metres
     * @param robotYM robot y in metres
     * @return true if a waypoint was reached by this call
     */
    public boolean update(double robotXM, double robotYM) {
        if (isDone()) {
            return false;
        }
        if (Math.hypot(xM[index] - robotXM, yM[index] - robotYM) <= toleranceM) {
            index++;
            return true;
        }
        return false;
    }

    /** @return true once every waypoint was reached (also true for an empty course) */
    public boolean isDone() {
        return index >= count;
    }

    /** @return number of waypoints */
    public int count() {
        return count;
    }

    /** @return index of the current waypoint ({@link #count()} when done) */
    public int index() {
        return index;
    }

    /** @return waypoints reached so far */
    public int reached() {
        return index;
    }

    /** @return the current waypoint's goal id (unique across course replacements) */
    public long currentGoalId() {
        return version * VERSION_STRIDE + index + 1;
    }

    /** @return x of the current waypoint in metres (the finish when done; 0 if empty) */
    public double currentXM() {
        return count == 0 ? 0 : xM[Math.min(index, count - 1)];
    }

    /** @return y of the current waypoint in metres (the finish when done; 0 if empty) */
    public double currentYM() {
        return count == 0 ? 0 : yM[Math.min(index, count - 1)];
    }

    /**
     * @param robotXM robot x in metres
     * @param robotYM robot y in metres
     * @return straight-line distance to the finish in metres (0 for an empty course)
     */
    public double distanceToFinishM(double robotXM, double robotYM) {
        return count == 0 ? 0 : Math.hypot(xM[count - 1] - robotXM, yM[count - 1] - robotYM);
    }
}
