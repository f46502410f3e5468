package io.rtaware.player.protocol;

import io.rtaware.robot.msg.LaserScan;

/**
 * A decoded laser DATA SCAN ({@code player_laser_data_t}) in reusable arrays, so decoding a
 * stream of scans does not allocate. Mutable; not thread-safe.
 */
public final class LaserData {

    /** Bearing of the first beam in radians. */
    public float minAngleRad;
    /** Bearing of the last beam in radians. */
    public float maxAngleRad;
    /** Angular resolution as sent (not used for bearings: see {@link LaserScan#bearingRad}). */
    public float resolutionRad;
    /** Maximum range in metres. */
    public float maxRangeM;
    /** Ranges in metres; the first {@link #rangeCount} are valid. */
    public final float[] rangesM;
    /** Number of valid ranges. */
    public int rangeCount;
    /** Intensities; the first {@link #intensityCount} are valid. */
    public final byte[] intensities;
    /** Number of valid intensities (0 when the scan carries none). */
    public int intensityCount;
    /** Scan id (always 0 with Player's rangertolaser driver). */
    public long id;

    /** @param capacity the most beams a scan may have; larger scans are rejected */
    public LaserData(int capacity) {
        rangesM = new float[capacity];
        intensities = new byte[capacity];
    }

    /**
     * Copies this scan into a data-store buffer. Player's laser interface declares no minimum
     * range, so the scan's is 0 (a reading of 0 is an obstacle at 0 m), and its resolution is
     * not trusted to imply a beam count (Stage's differs), so the scan implies none.
     *
     * @param out the destination
     * @param serverTimeS the message's header timestamp
     * @throws IllegalArgumentException if the scan has more beams than {@code out} holds
     */
    public void toLaserScan(LaserScan out, double serverTimeS) {
        out.setCount(rangeCount);
        System.arraycopy(rangesM, 0, out.rangesM, 0, rangeCount);
        out.minAngleRad = minAngleRad;
        out.maxAngleRad = maxAngleRad;
        out.maxRangeM = maxRangeM;
        out.minRangeM = 0;
        out.impliedBeams = 0;
        out.serverTimeS = serverTimeS;
    }
}
