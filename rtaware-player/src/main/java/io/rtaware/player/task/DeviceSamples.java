package io.rtaware.player.task;

import io.rtaware.robot.validate.SampleValidator;

/**
 * What one device delivered, for the report. Immutable and thread-safe.
 *
 * @param samples samples received and decoded (accepted plus rejected)
 * @param rejectedSamples samples that could not be true and were dropped, never published
 * @param lastRejection why the newest rejected sample could not be true, or null if none was
 * @param droppedBeams readings of a range device that said nothing (NaN, beyond the maximum
 *     range) and were dropped from scans that were kept; 0 for other devices
 */
public record DeviceSamples(long samples, long rejectedSamples, String lastRejection, long droppedBeams) {

    /**
     * @param checks a device's validator
     * @return its counts now
     */
    public static DeviceSamples of(SampleValidator checks) {
        long rejected = checks.rejected();
        return new DeviceSamples(checks.accepted() + rejected, rejected, checks.lastRejection(), checks.droppedBeams());
    }
}
