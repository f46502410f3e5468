package io.rtaware.nav.logic;

import io.rtaware.robot.msg.GoalSet;

/**
 * The path planner's goals, each tagged by the requester that added it. A requester adds and
 * removes its own goals (and removes a goal once it is reached); several goals may be present
 * at once, and the planner heads for the closest. Requesters are numbered {@code 0..n-1}.
 * Fixed capacity; not thread-safe; allocates nothing after construction.
 */
public final class GoalRegistry {

    private final int requesters;
    private final int[] requester;
    private final long[] id;
    private final double[] xM;
    private final double[] yM;
    private int count;

    /**
     * @param requesterCount number of requesters
     * @param capacity maximum number of goals over all requesters
     * @throws IllegalArgumentException if either is not positive
     */
    public GoalRegistry(int requesterCount, int capacity) {
        if (requesterCount <= 0) {
            throw new IllegalArgumentException("requesterCount must be > 0, got " + requesterCount);
        }
        if (capacity <= 0) {
            throw new IllegalArgumentException("capacity must be > 0, got " + capacity);
        }
        this.requesters = requesterCount;
        this.requester = new int[capacity];
        this.id = new long[capacity];
        this.xM = new double[capacity];
        this.yM = new double[capacity];
    }

    /** @return number of goals over all requesters */
    public int count() {
        return count;
    }

    /**
     * @param i goal slot, below {@link #count()}
     * @return the requester of that goal
     */
    public int requester(int i) {
        return requester[i];
    }

    /**
     * @param i goal slot
     * @return the goal's id
     */
    public long id(int i) {
        return id[i];
    }

    /**
     * @param i goal slot
     * @return the goal's x in metres
     */
    public double xM(int i) {
        return xM[i];
    }

    /**
     * @param i goal slot
     * @return the goal's y in metres
     */
    public double yM(int i) {
        return yM[i];
    }

    /**
     * Adds a goal, or moves it if this requester already has a goal with this id.
     *
     * @param requesterIndex the requester
     * @param goalId the goal's id, unique per requester
     * @param x x in metres
     * @param y y in metres
     * @return true if the registry changed
     * @throws IllegalStateException if full
     */
    public boolean add(int requesterIndex, long goalId, double x, double y) {
        checkRequester(requesterIndex);
        int i = find(requesterIndex, goalId);
        if (i >= 0) {
            boolean changed = xM[i] != x || yM[i] != y;
            xM[i] = x;
            yM[i] = y;
            return changed;
        }
        if (count == id.length) {
            throw new IllegalStateException("goal registry full (" + id.length + " goals)");
        }
        requester[count] = requesterIndex;
        id[count] = goalId;
        xM[count] = x;
        yM[count] = y;
        count++;
        return true;
    }

    /**
     * Removes one of a requester's goals.
     *
     * @param requesterIndex the requester
     * @param goalId the goal's id
     * @return true if it was present
     */
    public boolean remove(int requesterIndex, long goalId) {
        int i = find(requesterIndex, goalId);
        if (i < 0) {
            return false;
        }
        removeSlot(i);
        return true;
    }

    /**
     * Makes a requester's goals exactly those of a goal set: adds the new, moves the moved,
     * removes those no longer present. Other requesters' goals are untouched.
     *
     * @param requesterIndex the requester
     * @param goals its current goals
     * @return true if the registry changed
     */
    public boolean replace(int requesterIndex, GoalSet goals) {
        checkRequester(requesterIndex);
        boolean changed = false;
        for (int i = count - 1; i >= 0; i--) {
            if (requester[i] == requesterIndex && !containsId(goals, id[i])) {
                removeSlot(i);
                changed = true;
            }
        }
        for (int g = 0; g < goals.count(); g++) {
            changed |= add(requesterIndex, goals.id[g], goals.xM[g], goals.yM[g]);
        }
        return changed;
    }

    private static boolean containsId(GoalSet goals, long goalId) {
        for (int g = 0; g < goals.count(); g++) {
            if (goals.id[g] == goalId) {
                return true;
            }
        }
        return false;
    }

    private int find(int requesterIndex, long goalId) {
        for (int i = 0; i < count; i++) {
            if (requester[i] == requesterIndex && id[i] == goalId) {
                return i;
            }
        }
        return -1;
    }

    private void removeSlot(int i) {
        int tail = count - i - 1;
        System.arraycopy(requester, i + 1, requester, i, tail);
        System.arraycopy(id, i + 1, id, i, tail);
        System.arraycopy(xM, i + 1, xM, i, tail);
        System.arraycopy(yM, i + 1, yM, i, tail);
        count--;
    }

    private void checkRequester(int requesterIndex) {
        if (requesterIndex < 0 || requesterIndex >= requesters) {
            throw new IllegalArgumentException("requester " + requesterIndex + " outside 0.." + (requesters - 1));
        }
    }
}
