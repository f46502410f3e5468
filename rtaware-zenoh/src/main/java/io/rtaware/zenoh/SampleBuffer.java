package io.rtaware.zenoh;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;

/**
 * Preallocated memory for one received sample: a payload buffer, an attachment buffer, and the
 * channel and lengths of the sample last taken. Allocated once by the reader, filled by
 * {@link ZenohMailbox#take}. Not thread-safe: owned by the reader thread.
 */
public final class SampleBuffer {

    private final ByteBuffer payload;
    private final ByteBuffer attachment;
    private final ByteBuffer info = ByteBuffer.allocateDirect(12).order(ByteOrder.LITTLE_ENDIAN);

    /**
     * @param maxPayloadBytes the largest payload accepted (bigger samples are dropped)
     * @param maxAttachmentBytes the largest attachment accepted
     */
    public SampleBuffer(int maxPayloadBytes, int maxAttachmentBytes) {
        if (maxPayloadBytes <= 0 || maxAttachmentBytes < 0) {
            throw new IllegalArgumentException("buffer sizes must be positive: payload " + maxPayloadBytes
                    + ", attachment " + maxAttachmentBytes);
        }
        payload = ByteBuffer.allocateDirect(maxPayloadBytes);
        attachment = ByteBuffer.allocateDirect(Math.max(1, maxAttachmentBytes));
    }

    /** @return the channel of the subscriber the last sample came from */
    public int channel() {
        return info.getInt(0);
    }

    /** @return the last sample's payload length (for {@code TOO_LARGE}, its real size) */
    public int payloadLength() {
        return info.getInt(4);
    }

    /** @return the last sample's attachment length, -1 when it had none */
    public int attachmentLength() {
        return info.getInt(8);
    }

    /**
     * @return the payload memory (direct; bytes {@code [0, payloadLength())} are the last
     *     sample; position and limit are the caller's to use)
     */
    public ByteBuffer payload() {
        return payload;
    }

    /** @return the attachment memory (direct; bytes {@code [0, attachmentLength())}) */
    public ByteBuffer attachment() {
        return attachment;
    }

    ByteBuffer info() {
        return info;
    }
}
