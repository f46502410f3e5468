package io.rtaware.record;

import java.io.IOException;

/**
 * The writer thread's sink when the plan has a {@link RecordingTap}: every message goes to the
 * tap (log time made Unix-epoch ns, as in the file) and then to the file's sink, if there is a
 * file. Allocates nothing.
 */
final class TappedSink implements MessageSink {

    private final RecordingTap tap;
    private final MessageSink file;
    private final long offsetNs;

    /**
     * @param tap the tap
     * @param file the file's sink, or null when recording for the tap alone
     * @param logTimeOffsetNs added to world time to make log time
     */
    TappedSink(RecordingTap tap, MessageSink file, long logTimeOffsetNs) {
        this.tap = tap;
        this.file = file;
        this.offsetNs = logTimeOffsetNs;
    }

    @Override
    public void write(int channel, long sequence, long logTimeNs, long publishTimeNs, byte[] data, int offset,
                      int length) throws IOException {
        tap.message(channel, logTimeNs + offsetNs, data, offset, length);
        if (file != null) {
            file.write(channel, sequence, logTimeNs, publishTimeNs, data, offset, length);
        }
    }
}
