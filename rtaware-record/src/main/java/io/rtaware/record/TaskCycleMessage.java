package io.rtaware.record;

import io.rtaware.ros2msg.cdr.CdrReader;

/**
 * One decoded {@code rtaware_msgs/msg/TaskCycle} message (a {@code /rtaware/timing/<task>}
 * record). Allocates; for tools that read recordings, not for task threads.
 *
 * @param releaseNs scheduled release, world ns
 * @param startNs start
 * @param endNs end
 * @param latenessMs start - release in ms
 * @param execMs end - start in ms
 * @param outcome ok | miss | skipped | stale | error
 * @param skippedReleases releases skipped (outcome skipped)
 * @param inputGenerations generation of each input read
 */
public record TaskCycleMessage(long releaseNs, long startNs, long endNs, double latenessMs, double execMs,
                               String outcome, long skippedReleases, long[] inputGenerations) {

    /**
     * @param data buffer
     * @param offset first byte of the CDR message
     * @param length its length
     * @return the decoded message
     * @throws io.rtaware.ros2msg.cdr.CdrException if it is malformed
     */
    public static TaskCycleMessage decode(byte[] data, int offset, int length) {
        CdrReader r = new CdrReader().wrap(data, offset, length);
        long release = r.readInt64();
        long start = r.readInt64();
        long end = r.readInt64();
        double lateness = r.readFloat64();
        double exec = r.readFloat64();
        StringBuilder outcome = new StringBuilder(8);
        r.readString(outcome);
        long skipped = r.readInt64();
        int n = r.readSequenceLength(8);
        long[] generations = new long[n];
        for (int i = 0; i < n; i++) {
            generations[i] = r.readInt64();
        }
        return new TaskCycleMessage(release, start, end, lateness, exec, outcome.toString(), skipped, generations);
    }
}
