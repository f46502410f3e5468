package io.rtaware.robot.msg;

import io.rtaware.core.data.StateValue;

/**
 * One planar range scan (Player laser DATA SCAN or ranger DATA RANGE, ROS 2
 * {@code sensor_msgs/msg/LaserScan}). Beam {@code i} points at {@link #bearingRad(int)}: beams are
 * spread evenly from {@link #minAngleRad} to {@link #maxAngleRad} inclusive, computed as
 * (max - min) / (count - 1), not from the server's resolution field (Stage's differs;
 * PROTOCOL.md section 10.9).
 *
 * <p>What a reading means, for every consumer (REP 117 in the robot's terms):
 * <ul>
 *   <li>below {@link #minRangeM} (including 0 and {@code -Inf}): something is closer than the
 *       sensor can measure: an obstacle <em>at</em> the minimum range ({@link #obstacleRangeM});</li>
 *   <li>at or beyond {@link #maxRangeM} (including {@code +Inf}): nothing was hit within range;</li>
 *   <li>NaN: no reading (erroneous, or dropped by the plausibility checks); it says nothing.</li>
 * </ul>
 * Fixed capacity, mutable buffer for the data store; not thread-safe.
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
    /**
     * minimum range in metres (0 where the source does not say); readings below it mean
     * something is closer than the sensor can measure.
     */
    public double minRangeM;
    /**
     * beams the source's own angles imply (from its declared angular increment), or 0 where the
     * source does not declare one; a scan with fewer beams than that is impossible data.
     */
    public int impliedBeams;
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
     * The distance at which a reading places an obstacle, by the rules of this class.
     *
     * @param beam beam index
     * @return the reading, raised to {@link #minRangeM} when it is below it (closer than the
     *     sensor can measure); {@code +Inf} and readings at or beyond the maximum range come back
     *     as they are (compare with {@link #maxRangeM}); NaN for no reading
     */
    public double obstacleRangeM(int beam) {
        double r = rangesM[beam];
        return r < minRangeM ? minRangeM : r;
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
        minRangeM = s.minRangeM;
        impliedBeams = s.impliedBeams;
        serverTimeS = s.serverTimeS;
        setCount(s.count);
        System.arraycopy(s.rangesM, 0, rangesM, 0, s.count);
    }
}
