package io.rtaware.record;

import java.io.IOException;

/**
 * The writer thread's sink when the plan has a {@link RecordingTap}: every message goes to the
 * tap's reorder window and then to the file's, if there is a file. Each window orders on its own
 * ({@link LogTimeOrderedSink}): the tap's with the plan's reorder window and nothing more, so the
 * live feed is never later than that window (the file's also waits for the {@code /statistics}
 * window to be published), and drops what comes too late rather than send a channel back in time.
 * Allocates nothing once the windows' slots have grown.
 */
final class TappedSink implements MessageSink {

    private final LogTimeOrderedSink tap;
    private final MessageSink file;

    /**
     * @param tap the tap's reorder window ({@link #forTap})
     * @param file the file's sink, or null when recording for the tap alone
     */
    TappedSink(LogTimeOrderedSink tap, MessageSink file) {
        this.tap = tap;
        this.file = file;
    }

    /**
     * @param tap the tap
     * @param logTimeOffsetNs added to world time to make log time (Unix-epoch ns, as in the file)
     * @param windowNs the reorder window, world time
     * @param slots most messages held at once
     * @param budgetBytes most message bytes held at once
     * @return a reorder window that passes messages on to the tap, dropping those that come too late
     */
    static LogTimeOrderedSink forTap(RecordingTap tap, long logTimeOffsetNs, long windowNs, int slots,
                                     long budgetBytes) {
        return new LogTimeOrderedSink((channel, sequence, logTimeNs, publishTimeNs, data, offset, length)
                -> tap.message(channel, logTimeNs, data, offset, length), true, logTimeOffsetNs, windowNs, slots,
                budgetBytes);
    }

    @Override
    public void write(int channel, long sequence, long logTimeNs, long publishTimeNs, byte[] data, int offset,
                      int length) throws IOException {
        tap.write(channel, sequence, logTimeNs, publishTimeNs, data, offset, length);
        if (file != null) {
            file.write(channel, sequence, logTimeNs, publishTimeNs, data, offset, length);
        }
    }

    /**
     * Passes every message the tap's window still holds to the tap (at the end of the recording).
     *
     * @throws IOException never from a tap; declared by the window
     */
    void flush() throws IOException {
        tap.flush();
    }
}
