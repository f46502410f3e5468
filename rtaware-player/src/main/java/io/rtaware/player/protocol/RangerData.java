package io.rtaware.player.protocol;

import io.rtaware.robot.msg.LaserScan;

/**
 * A decoded ranger DATA RANGE or DATA INTNS ({@code player_ranger_data_range_t} /
 * {@code player_ranger_data_intns_t}: count and doubles) in a reusable array. Mutable; not
 * thread-safe.
 */
public final class RangerData {

    /** The values (metres for RANGE); the first {@link #count} are valid. */
    public final double[] values;
    /** Number of valid values. */
    public int count;

    /** @param capacity the most values a message may have; larger ones are rejected */
    public RangerData(int capacity) {
        values = new double[capacity];
    }

    /**
     * Converts ranges into a scan, with the angles and the minimum and maximum range from the
     * ranger's configuration (the RANGE message carries none of them); the scan implies no beam
     * count.
     *
     * @param out the destination
     * @param config the ranger's GET_CONFIG reply
     * @param serverTimeS the message's header timestamp
     * @throws IllegalArgumentException if there are more values than {@code out} holds
     */
    public void toLaserScan(LaserScan out, RangerConfig config, double serverTimeS) {
        out.setCount(count);
        for (int i = 0; i < count; i++) {
            out.rangesM[i] = (float) values[i];
        }
        out.minAngleRad = config.minAngleRad();
        out.maxAngleRad = config.maxAngleRad();
        out.maxRangeM = config.maxRangeM();
        out.minRangeM = config.minRangeM();
        out.impliedBeams = 0;
        out.serverTimeS = serverTimeS;
    }
}
