package io.rtaware.ros2msg.value;

/**
 * One {@code diagnostic_msgs/msg/DiagnosticStatus}: a level, a name, a message, a hardware id and
 * up to a fixed number of key/value pairs. Mutable; text lives in {@link StringBuilder}s that
 * are reused. Not thread-safe.
 */
public final class DiagnosticStatus {

    /** Level: fine. */
    public static final byte OK = 0;
    /** Level: warning. */
    public static final byte WARN = 1;
    /** Level: error. */
    public static final byte ERROR = 2;
    /** Level: no recent data. */
    public static final byte STALE = 3;

    /** one of {@link #OK}, {@link #WARN}, {@link #ERROR}, {@link #STALE}. */
    public byte level;
    /** what is described. */
    public final StringBuilder name = new StringBuilder(64);
    /** the state in words. */
    public final StringBuilder message = new StringBuilder(64);
    /** the hardware concerned (may be empty). */
    public final StringBuilder hardwareId = new StringBuilder(16);
    private final StringBuilder[] keys;
    private final StringBuilder[] values;
    private int valueCount;

    /** @param capacityValues maximum number of key/value pairs */
    public DiagnosticStatus(int capacityValues) {
        keys = new StringBuilder[capacityValues];
        values = new StringBuilder[capacityValues];
        for (int i = 0; i < capacityValues; i++) {
            keys[i] = new StringBuilder(32);
            values[i] = new StringBuilder(32);
        }
    }

    /** Empties the status: level OK, no text, no values. */
    public void clear() {
        level = OK;
        name.setLength(0);
        message.setLength(0);
        hardwareId.setLength(0);
        valueCount = 0;
    }

    /** @return number of key/value pairs */
    public int valueCount() {
        return valueCount;
    }

    /** @return maximum number of key/value pairs */
    public int valueCapacity() {
        return keys.length;
    }

    /**
     * Appends an empty key/value pair.
     *
     * @return its index; fill it through {@link #key(int)} and {@link #value(int)}
     * @throws IllegalStateException if full
     */
    public int addValue() {
        if (valueCount == keys.length) {
            throw new IllegalStateException("diagnostic status full (" + keys.length + " values)");
        }
        keys[valueCount].setLength(0);
        values[valueCount].setLength(0);
        return valueCount++;
    }

    /**
     * @param i index below {@link #valueCount()}
     * @return the pair's key
     */
    public StringBuilder key(int i) {
        return keys[checked(i)];
    }

    /**
     * @param i index below {@link #valueCount()}
     * @return the pair's value
     */
    public StringBuilder value(int i) {
        return values[checked(i)];
    }

    private int checked(int i) {
        if (i < 0 || i >= valueCount) {
            throw new IndexOutOfBoundsException("value " + i + " of " + valueCount);
        }
        return i;
    }
}
