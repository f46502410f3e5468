package io.rtaware.record;

/**
 * What sees a recording's channels and messages besides its file: a live server (Foxglove's
 * WebSocket protocol) that shows a running rtaware as a ROS 2 robot, with the same channels,
 * schemas and CDR as the file ({@link RecordingPlan#tap}). The recorder works without a file
 * too, for its tap alone.
 *
 * <p>Channels come first, from the thread that creates the recorder, before any message.
 * Messages come from one thread at a time: the recorder's writer thread (and, for
 * {@code /tf_static}, the creating thread before the writer thread starts), in the order the
 * writer drains the rings, before the file's reorder window: within a few milliseconds of their
 * commit, in log-time order per channel but not across channels. The task threads never call a
 * tap. A tap must not block and must not throw: what it cannot send it drops and counts.
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
