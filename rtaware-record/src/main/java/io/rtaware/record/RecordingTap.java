package io.rtaware.record;

/**
 * What sees a recording's channels and messages besides its file: a live server (Foxglove's
 * WebSocket protocol) that shows a running rtaware as a ROS 2 robot, with the same channels,
 * schemas and CDR as the file ({@link RecordingPlan#tap}). The recorder works without a file
 * too, for its tap alone.
 *
 * <p>Channels come first, from the thread that creates the recorder, before any message.
 * Messages come from one thread at a time: the recorder's writer thread (and, for
 * {@code /tf_static}, the creating thread, at the latest when the writer thread finishes), in
 * log-time order on every channel and across channels: through a reorder window of the tap's own
 * (the plan's {@link RecordingPlan#reorderWindowNs}), so at most that much world time after
 * their commit; a message that comes later than that, after a newer one was sent, is not sent.
 * The task threads never call a tap. A tap must not block and must not throw: what it cannot send it drops and counts.
 */
public interface RecordingTap {

    /**
     * A channel of the recording.
     *
     * @param channel its id, topic, ROS 2 type and schema
     */
    void channel(TapChannel channel);

    /**
     * One encoded message (CDR of the channel's type).
     *
     * @param channelId the channel's id ({@link TapChannel#id})
     * @param logTimeNs its log time, Unix-epoch ns (as in the file)
     * @param data the message's bytes (valid only during the call)
     * @param offset first byte
     * @param length bytes
     */
    void message(int channelId, long logTimeNs, byte[] data, int offset, int length);
}
