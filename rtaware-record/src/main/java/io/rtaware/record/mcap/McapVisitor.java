package io.rtaware.record.mcap;

import java.util.Map;

/** Receives a file's records in file order from {@link McapReader#read}. */
public interface McapVisitor {

    /** @param schema a schema record */
    default void schema(McapSchema schema) {
    }

    /** @param channel a channel record (its schema came before) */
    default void channel(McapChannel channel) {
    }

    /**
     * @param name a metadata record's name
     * @param entries its key/value pairs
     */
    default void metadata(String name, Map<String, String> entries) {
    }

    /**
     * A chunk, before its records (its CRC checked).
     *
     * @param fileOffset where the chunk record starts in the file
     * @param startNs the chunk's earliest message log time, as recorded
     * @param endNs its latest, as recorded
     */
    default void chunk(long fileOffset, long startNs, long endNs) {
    }

    /**
     * A message. The bytes are only valid during the call.
     *
     * @param channel its channel
     * @param sequence the channel's sequence number
     * @param logTimeNs log time
     * @param publishTimeNs publish time
     * @param data buffer holding the message
     * @param offset first byte
     * @param length number of bytes
     */
    void message(McapChannel channel, long sequence, long logTimeNs, long publishTimeNs,
                 byte[] data, int offset, int length);
}
