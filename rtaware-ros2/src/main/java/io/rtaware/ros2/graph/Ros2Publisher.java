package io.rtaware.ros2.graph;

import io.rtaware.zenoh.LivelinessToken;
import io.rtaware.zenoh.ZenohException;
import io.rtaware.zenoh.ZenohPublisher;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import net.openhft.hashing.LongTupleHashFunction;

/**
 * A ROS 2 publisher: copies an encoded message into its own direct buffer and publishes it with
 * the rmw_zenoh attachment (a sequence number from 1, the source timestamp, its gid), or on DDS
 * without one (the bridge forwards payloads only). Allocates nothing per message. One thread at
 * a time.
 */
public final class Ros2Publisher implements AutoCloseable {

    private final ZenohPublisher publisher;
    private final LivelinessToken token;
    private final byte[] gid;
    private final ByteBuffer payload;
    private final ByteBuffer attachment = ByteBuffer.allocateDirect(SampleAttachment.BYTES);
    private long sequence;

    Ros2Publisher(ZenohPublisher publisher, LivelinessToken token, byte[] gid, int maxMessageBytes) {
        this.publisher = publisher;
        this.token = token;
        this.gid = gid;
        this.payload = ByteBuffer.allocateDirect(maxMessageBytes);
    }

    /**
     * An entity's gid as rmw_zenoh derives it (rmw_zenoh_cpp {@code liveliness::Entity}'s
     * constructor in {@code src/detail/liveliness_utils.cpp}, the same on the Humble, Jazzy,
     * Kilted and Rolling branches): XXH3-128 (seed 0, default secret) of the entity's whole
     * liveliness key expression, its low 64 bits then its high 64 bits, each little endian.
     * This is the gid a subscriber receives in the attachment and {@code ros2 topic info -v}
     * shows for the publisher.
     *
     * @param livelinessKey the entity's liveliness token key ({@code @ros2_lv/...})
     * @return the 16-byte gid
     */
    public static byte[] gid(String livelinessKey) {
        byte[] key = livelinessKey.getBytes(StandardCharsets.UTF_8);
        long[] hash = LongTupleHashFunction.xx128().hashBytes(key);
        ByteBuffer gid = ByteBuffer.allocate(SampleAttachment.GID_BYTES).order(ByteOrder.LITTLE_ENDIAN);
        gid.putLong(hash[0]).putLong(hash[1]);
        return gid.array();
    }

    /** @return a copy of this publisher's gid, or null on DDS (where the bridge writes its own) */
    public byte[] gid() {
        return gid == null ? null : gid.clone();
    }

    /**
     * Publishes one CDR message.
     *
     * @param message the message bytes, encapsulation header included
     * @param length how many bytes
     * @param sourceTimestampNs the source timestamp in ns since the Unix epoch
     * @throws ZenohException if it cannot be published
     * @throws IllegalArgumentException if the message is bigger than this publisher's maximum
     */
    public void publish(byte[] message, int length, long sourceTimestampNs) throws ZenohException {
        if (length > payload.capacity()) {
            throw new IllegalArgumentException("message of " + length + " bytes exceeds the publisher's maximum of "
                    + payload.capacity() + " on " + publisher.key());
        }
        payload.clear();
        payload.put(message, 0, length);
        ++sequence;
        if (gid == null) {
            publisher.put(payload, length, null, -1);
        } else {
            SampleAttachment.write(attachment, sequence, sourceTimestampNs, gid);
            publisher.put(payload, length, attachment, SampleAttachment.BYTES);
        }
    }

    /** @return the topic key expression */
    public String key() {
        return publisher.key();
    }

    /** @return the liveliness key of this publisher */
    public String tokenKey() {
        return token.key();
    }

    /** @return messages published */
    public long published() {
        return sequence;
    }

    /** Undeclares the token and the publisher. */
    @Override
    public void close() throws ZenohException {
        try {
            token.close();
        } finally {
            publisher.close();
        }
    }
}
