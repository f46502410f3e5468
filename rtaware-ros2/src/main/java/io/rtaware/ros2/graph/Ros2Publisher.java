package io.rtaware.ros2.graph;

import io.rtaware.zenoh.LivelinessToken;
import io.rtaware.zenoh.ZenohException;
import io.rtaware.zenoh.ZenohPublisher;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.Arrays;

/**
 * A ROS 2 publisher: copies an encoded message into its own direct buffer and publishes it with
 * the rmw_zenoh attachment (a sequence number from 1, the source timestamp, its gid). Allocates
 * nothing per message. One thread at a time.
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
     * A gid derived from the session id and the entity id, so that it is unique in the graph
     * and the same on every run of the same session.
     */
    static byte[] gid(String zid, long entityId) {
        try {
            byte[] digest = MessageDigest.getInstance("SHA-256")
                    .digest((zid + "/" + entityId).getBytes(StandardCharsets.US_ASCII));
            return Arrays.copyOf(digest, SampleAttachment.GID_BYTES);
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-256 is part of every JDK", e);
        }
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
        SampleAttachment.write(attachment, ++sequence, sourceTimestampNs, gid);
        publisher.put(payload, length, attachment, SampleAttachment.BYTES);
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
