package io.rtaware.robot.msg;

import io.rtaware.core.data.StateValue;

/**
 * One planar range scan (Player laser DATA SCAN or ranger DATA RANGE). Beam {@code i} points
 * at {@link #bearingRad(int)}: beams are spread evenly from {@link #minAngleRad} to
 * {@link #maxAngleRad} inclusive, computed as (max - min) / (count - 1), not from the
 * server's resolution field (Stage's differs; PROTOCOL.md section 10.9). Fixed capacity,
 * mutable buffer for the data store; not thread-safe.
 */
public final class LaserScan implements StateValue<LaserScan> {

    /** Default capacity: more beams than any laser Player drives. */
    public static final int DEFAULT_CAPACITY = 4096;

    /** bearing of the first beam in radians, relative to the robot's heading. */
    public double minAngleRad;
    /** bearing of the last beam in radians. */
    public double maxAngleRad;
    /** maximum range in metres; readings at or beyond it mean nothing was hit. */
    public double maxRangeM;
    /** the robot server's timestamp in seconds. */
    public double serverTimeS;
    /** range of each beam in metres; only the first {@link #count} are valid. */
    public final float[] rangesM;
    private int count;

    /** A scan with {@link #DEFAULT_CAPACITY} beams of capacity. */
    public LaserScan() {
        this(DEFAULT_CAPACITY);
    }

    /** @param capacity maximum number of beams */
    public LaserScan(int capacity) {
        this.rangesM = new float[capacity];
    }

    /** @return number of valid beams */
    public int count() {
        return count;
    }

    /**
     * @param beams number of valid beams
     * @throws IllegalArgumentException if negative or above the capacity
     */
    public void setCount(int beams) {
        if (beams < 0 || beams > rangesM.length) {
            throw new IllegalArgumentException("beam count " + beams + " outside 0.." + rangesM.length);
        }
        this.count = beams;
    }

    /** @return the angle between neighbouring beams in radians (0 with fewer than two beams) */
    public double angleIncrementRad() {
        return count < 2 ? 0.0 : (maxAngleRad - minAngleRad) / (count - 1);
    }

    /**
     * @param beam beam index
     * @return the beam's bearing in radians relative to the robot's heading
     */
    public double bearingRad(int beam) {
        return minAngleRad + beam * angleIncrementRad();
    }

    @Override
    public void copyFrom(LaserScan s) {
        minAngleRad = s.minAngleRad;
        maxAngleRad = s.maxAngleRad;
        maxRangeM = s.maxRangeM;
        serverTimeS = s.serverTimeS;
        setCount(s.count);
        System.arraycopy(s.rangesM, 0, rangesM, 0, s.count);
    }
}
