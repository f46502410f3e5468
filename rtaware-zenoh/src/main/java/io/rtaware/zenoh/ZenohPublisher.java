package io.rtaware.zenoh;

import java.nio.ByteBuffer;

/**
 * A publisher on one key expression. {@link #put} reads the caller's direct buffers and
 * allocates nothing on the Java heap. Safe to use from one thread at a time; {@link #close} may
 * come from any thread (a {@code put} racing it either publishes or throws).
 */
public final class ZenohPublisher implements AutoCloseable {

    private final ZenohSession session;
    private final String key;
    private volatile long handle;

    ZenohPublisher(ZenohSession session, String key, long handle) {
        this.session = session;
        this.key = key;
        this.handle = handle;
    }

    /** @return the key expression */
    public String key() {
        return key;
    }

    /**
     * Publishes bytes {@code [0, length)} of {@code payload} with bytes
     * {@code [0, attachmentLength)} of {@code attachment}.
     *
     * @param payload a direct buffer (its position and limit are ignored)
     * @param length payload bytes
     * @param attachment a direct buffer, or null for no attachment
     * @param attachmentLength attachment bytes (ignored when {@code attachment} is null)
     * @throws ZenohException if a length exceeds its buffer's capacity, a buffer is not
     *     direct, or the publisher is closed
     */
    public void put(ByteBuffer payload, int length, ByteBuffer attachment, int attachmentLength) throws ZenohException {
        long h = handle;
        if (h == 0) {
            throw new ZenohException("publisher on " + key + " is closed");
        }
        NativeZenoh.put(h, payload, length, attachment == null ? payload : attachment,
                attachment == null ? -1 : attachmentLength);
    }

    /** Undeclares the publisher. Idempotent. */
    @Override
    public synchronized void close() throws ZenohException {
        if (handle == 0) {
            return;
        }
        long h = handle;
        handle = 0;
        session.forget(this);
        NativeZenoh.undeclarePublisher(h);
    }
}
