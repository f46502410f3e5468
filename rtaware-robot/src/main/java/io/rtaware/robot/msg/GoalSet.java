package io.rtaware.robot.msg;

import io.rtaware.core.data.StateValue;

/**
 * An ordered set of goal positions, each with an id chosen by whoever wrote it: one
 * requester's goal requests to the path planner, or a list of waypoints. Fixed capacity,
 * mutable buffer for the data store; {@link #copyFrom} copies without allocating. Not
 * thread-safe.
 */
public final class GoalSet implements StateValue<GoalSet> {

    /** Default capacity in goals. */
    public static final int DEFAULT_CAPACITY = 64;

    /** x of each goal in metres; only the first {@link #count()} are valid. */
    public final double[] xM;
    /** y of each goal in metres. */
    public final double[] yM;
    /** id of each goal. */
    public final long[] id;
    private int count;

    /** A set with {@link #DEFAULT_CAPACITY} goals of capacity. */
    public GoalSet() {
        this(DEFAULT_CAPACITY);
    }

    /** @param capacity maximum number of goals */
    public GoalSet(int capacity) {
        this.xM = new double[capacity];
        this.yM = new double[capacity];
        this.id = new long[capacity];
    }

    /** @return number of valid goals */
    public int count() {
        return count;
    }

    /** @return maximum number of goals */
    public int capacity() {
        return xM.length;
    }

    /** Removes every goal. */
    public void clear() {
        count = 0;
    }

    /**
     * Appends a goal.
     *
     * @param goalId the goal's id
     * @param x x in metres
     * @param y y in metres
     * @throws IllegalStateException if the set is full
     */
    public void add(long goalId, double x, double y) {
        if (count == xM.length) {
            throw new IllegalStateException("goal set full (" + xM.length + " goals)");
        }
        xM[count] = x;
        yM[count] = y;
        id[count] = goalId;
        count++;
    }

    /**
     * Removes the goal with an id, keeping the order of the others.
     *
     * @param goalId the id
     * @return true if a goal was removed
     */
    public boolean remove(long goalId) {
        for (int i = 0; i < count; i++) {
            if (id[i] == goalId) {
                int tail = count - i - 1;
                System.arraycopy(xM, i + 1, xM, i, tail);
                System.arraycopy(yM, i + 1, yM, i, tail);
                System.arraycopy(id, i + 1, id, i, tail);
                count--;
                return true;
            }
        }
        return false;
    }

    @Override
    public void copyFrom(GoalSet s) {
        if (s.count > xM.length) {
            throw new IllegalArgumentException("goal set of " + s.count + " exceeds capacity " + xM.length);
        }
        System.arraycopy(s.xM, 0, xM, 0, s.count);
        System.arraycopy(s.yM, 0, yM, 0, s.count);
        System.arraycopy(s.id, 0, id, 0, s.count);
        count = s.count;
    }
}
