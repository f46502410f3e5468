package io.rtaware.ros2.graph;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;

/**
 * The attachment rmw_zenoh puts on every sample (33 bytes): the publisher's sequence number
 * (int64, little endian), the source timestamp in nanoseconds since the Unix epoch (int64,
 * little endian), the gid length (one byte, 16), and the publisher's 16-byte gid. Stateless.
 */
public final class SampleAttachment {

    /** Bytes of an attachment. */
    public static final int BYTES = 33;
    /** Bytes of a gid. */
    public static final int GID_BYTES = 16;
    /** Where the gid starts in an attachment. */
    public static final int GID_OFFSET = 17;

    private SampleAttachment() {
    }

    /**
     * Writes an attachment at index 0 of {@code into} (in little endian whatever the buffer's
     * byte order; allocates nothing).
     *
     * @param into at least {@link #BYTES} bytes
     * @param sequence the sequence number
     * @param sourceTimestampNs the source timestamp in ns since the Unix epoch
     * @param gid the publisher's gid, {@link #GID_BYTES} bytes
     */
    public static void write(ByteBuffer into, long sequence, long sourceTimestampNs, byte[] gid) {
        boolean little = into.order() == ByteOrder.LITTLE_ENDIAN;
        into.putLong(0, little ? sequence : Long.reverseBytes(sequence));
        into.putLong(8, little ? sourceTimestampNs : Long.reverseBytes(sourceTimestampNs));
        into.put(16, (byte) GID_BYTES);
        into.put(GID_OFFSET, gid, 0, GID_BYTES);
    }

    /**
     * @param attachment the received attachment's memory
     * @param length its length (-1 when the sample had none)
     * @return whether it has the rmw_zenoh form
     */
    public static boolean valid(ByteBuffer attachment, int length) {
        return length == BYTES && attachment.get(16) == GID_BYTES;
    }

    /**
     * @param attachment a {@link #valid} attachment
     * @return its sequence number
     */
    public static long sequence(ByteBuffer attachment) {
        return littleEndianLong(attachment, 0);
    }

    /**
     * @param attachment a {@link #valid} attachment
     * @return its source timestamp in ns since the Unix epoch
     */
    public static long sourceTimestampNs(ByteBuffer attachment) {
        return littleEndianLong(attachment, 8);
    }

    private static long littleEndianLong(ByteBuffer b, int at) {
        long big = b.getLong(at);
        return b.order() == ByteOrder.LITTLE_ENDIAN ? big : Long.reverseBytes(big);
    }
}
