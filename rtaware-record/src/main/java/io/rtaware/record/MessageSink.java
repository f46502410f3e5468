package io.rtaware.record;

import java.io.IOException;

/** Where the writer thread puts encoded messages: the MCAP writer, in log-time order. */
interface MessageSink {

    /**
     * @param channel an MCAP channel id
     * @param sequence the message's sequence number (generation or record number)
     * @param logTimeNs world time of the record (the sink maps it to the file's log time)
     * @param publishTimeNs world time of the record's publication
     * @param data the encoded message
     * @param offset first byte
     * @param length bytes
     * @throws IOException if the file cannot be written
     */
    void write(int channel, long sequence, long logTimeNs, long publishTimeNs, byte[] data, int offset, int length)
            throws IOException;
}
