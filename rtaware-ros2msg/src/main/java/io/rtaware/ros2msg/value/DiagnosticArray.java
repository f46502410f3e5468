package io.rtaware.ros2msg.value;

/**
 * A {@code diagnostic_msgs/msg/DiagnosticArray} without its header: up to a fixed number of
 * statuses, each with up to a fixed number of key/value pairs, all allocated once. Not
 * thread-safe.
 */
public final class DiagnosticArray {

    private final DiagnosticStatus[] statuses;
    private int count;

    /**
     * @param capacityStatuses maximum number of statuses
     * @param capacityValuesPerStatus maximum number of key/value pairs in one status
     */
    public DiagnosticArray(int capacityStatuses, int capacityValuesPerStatus) {
        statuses = new DiagnosticStatus[capacityStatuses];
        for (int i = 0; i < capacityStatuses; i++) {
            statuses[i] = new DiagnosticStatus(capacityValuesPerStatus);
        }
    }

    /** Removes every status. */
    public void clear() {
        count = 0;
    }

    /** @return number of statuses */
    public int count() {
        return count;
    }

    /** @return maximum number of statuses */
    public int capacity() {
        return statuses.length;
    }

    /**
     * Appends a cleared status.
     *
     * @return it, to be filled
     * @throws IllegalStateException if full
     */
    public DiagnosticStatus add() {
        if (count == statuses.length) {
            throw new IllegalStateException("diagnostic array full (" + statuses.length + " statuses)");
        }
        DiagnosticStatus s = statuses[count++];
        s.clear();
        return s;
    }

    /**
     * @param i index below {@link #count()}
     * @return that status
     */
    public DiagnosticStatus status(int i) {
        if (i < 0 || i >= count) {
            throw new IndexOutOfBoundsException("status " + i + " of " + count);
        }
        return statuses[i];
    }
}
