package io.rtaware.record;

import io.rtaware.record.encode.TimingTypes;
import io.rtaware.ros2msg.cdr.CdrWriter;

/**
 * Encodes the recorder's own records as CDR of rtaware's message types
 * ({@link TimingTypes#TASK_CYCLE}, {@link TimingTypes#MONITOR_EVENT}). Stateless; allocates
 * nothing.
 */
final class TimingEncoder {

    private static final String[] OUTCOMES = {TimingTypes.OK, TimingTypes.MISS, TimingTypes.SKIPPED,
        TimingTypes.STALE, TimingTypes.ERROR};
    private static final String[] EVENT_KINDS = {"deadline_miss", "expired_read", "period_change", "task_error"};

    private TimingEncoder() {
    }

    /**
     * Encodes one {@code rtaware_msgs/msg/TaskCycle}.
     *
     * @param cdr the buffer (restarted)
     * @param outcome a {@link RunRecorder} outcome code
     * @param releaseNs release
     * @param startNs start
     * @param endNs end
     * @param skippedReleases releases skipped
     * @param generations input generations
     * @param from index of the first in {@code generations}
     * @param inputs how many
     */
    static void cycle(CdrWriter cdr, byte outcome, long releaseNs, long startNs, long endNs, long skippedReleases,
                      long[] generations, int from, int inputs) {
        cdr.begin();
        cdr.writeInt64(releaseNs);
        cdr.writeInt64(startNs);
        cdr.writeInt64(endNs);
        cdr.writeFloat64(Math.max(0, startNs - releaseNs) / 1e6);
        cdr.writeFloat64((endNs - startNs) / 1e6);
        cdr.writeString(OUTCOMES[outcome]);
        cdr.writeInt64(skippedReleases);
        cdr.writeSequenceLength(inputs);
        for (int k = 0; k < inputs; k++) {
            cdr.writeInt64(generations[from + k]);
        }
    }

    /**
     * Encodes one {@code rtaware_msgs/msg/MonitorEvent}.
     *
     * @param cdr the buffer (restarted)
     * @param kind a {@link RunRecorder} event kind
     * @param task the task's name
     * @param key the input's key name, or null
     * @param timeNs the event's world time
     * @param a release (miss), age (expired read), old period (period change)
     * @param b deadline (miss), maximum age (expired read), new period (period change)
     * @param flag still running (miss)
     * @param detail the error or reason, or null
     */
    static void event(CdrWriter cdr, byte kind, String task, String key, long timeNs, long a, long b, boolean flag,
                      Object detail) {
        cdr.begin();
        cdr.writeString(EVENT_KINDS[kind]);
        cdr.writeString(task);
        cdr.writeString(key == null ? "" : key);
        cdr.writeInt64(timeNs);
        cdr.writeInt64(kind == RunRecorder.DEADLINE_MISS ? a : 0);
        cdr.writeInt64(kind == RunRecorder.DEADLINE_MISS ? b : 0);
        cdr.writeBool(kind == RunRecorder.DEADLINE_MISS && flag);
        cdr.writeInt64(kind == RunRecorder.EXPIRED_READ ? a : 0);
        cdr.writeInt64(kind == RunRecorder.EXPIRED_READ ? b : 0);
        cdr.writeInt64(kind == RunRecorder.PERIOD_CHANGE ? a : 0);
        cdr.writeInt64(kind == RunRecorder.PERIOD_CHANGE ? b : 0);
        cdr.writeString(detail == null ? "" : detail.toString());
    }
}
