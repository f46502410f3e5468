package io.rtaware.ros2.task;

/**
 * Counters of a {@link Ros2DataTask}, a snapshot. Immutable.
 *
 * @param scans scans committed
 * @param odometry odometry samples committed
 * @param commands Twist messages published (zero stops included)
 * @param malformed samples dropped because they could not be decoded (wrong encapsulation,
 *     truncated, inconsistent lengths)
 * @param oversized samples dropped because they exceeded the largest accepted message
 * @param scanRejected decoded scans dropped because their values cannot be true
 * @param odomRejected decoded odometry samples dropped because their values cannot be true
 * @param overflowed samples dropped because the task fell behind
 * @param otherPublishers samples dropped because another publisher than the followed one of
 *     their topic sent them
 * @param clockEpochs new epochs of a topic's clock followed (a restarted or jumped source clock)
 * @param lastProblem the last reason a sample was dropped, or null
 * @param droppedBeams readings that said nothing (NaN, beyond the maximum range) dropped from
 *     scans, which were kept while they had a usable beam
 */
public record Ros2Stats(long scans, long odometry, long commands, long malformed, long oversized, long scanRejected,
                        long odomRejected, long overflowed, long otherPublishers, long clockEpochs,
                        String lastProblem, long droppedBeams) {

    /** @return decoded samples of either topic dropped because their values cannot be true */
    public long rejected() {
        return scanRejected + odomRejected;
    }

    /** @return samples dropped for any reason */
    public long dropped() {
        return malformed + oversized + rejected() + overflowed + otherPublishers;
    }
}
