package io.rtaware.player.protocol;

import io.rtaware.player.xdr.PlayerProtocolException;
import io.rtaware.player.xdr.XdrReader;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.util.Arrays;

/**
 * Cuts the byte stream after the banner into messages (40-byte header + body). It survives
 * partial reads and read timeouts: a {@link java.net.SocketTimeoutException} from the stream
 * propagates and the bytes already received are kept, so the next {@link #read} resumes the
 * same message. A header whose size is negative or above {@link #maxBodyBytes()} is rejected
 * before the body buffer grows; after that, or after the stream ends inside a message, the
 * stream is unusable. The body buffer is reused between messages. Not thread-safe.
 */
public final class PlayerFrameReader {

    /** Default largest body accepted: 4 MiB (Stage laser scans are about 1 KiB). */
    public static final int DEFAULT_MAX_BODY_BYTES = 4 << 20;

    private final int maxBodyBytes;
    private final XdrReader reader = new XdrReader();
    private byte[] buf = new byte[8192];
    private int filled;
    private int frameBytes = PlayerHeader.SIZE_BYTES;
    private PlayerHeader header;
    private boolean complete;
    private long frameStart;
    private long bytesRead;
    private long messages;
    private PlayerProtocolException broken;

    /**
     * @param streamStart stream offset of the first message (32 after the banner), used in
     *     error messages
     * @param maxBodyBytes largest body accepted (1 .. 2^31 - 41)
     * @throws IllegalArgumentException if the limit is out of range
     */
    public PlayerFrameReader(long streamStart, int maxBodyBytes) {
        if (maxBodyBytes < 1 || maxBodyBytes > Integer.MAX_VALUE - PlayerHeader.SIZE_BYTES) {
            throw new IllegalArgumentException("maxBodyBytes " + maxBodyBytes + " outside 1.."
                    + (Integer.MAX_VALUE - PlayerHeader.SIZE_BYTES));
        }
        this.maxBodyBytes = maxBodyBytes;
        this.frameStart = streamStart;
    }

    /** @return the largest body accepted, in bytes */
    public int maxBodyBytes() {
        return maxBodyBytes;
    }

    /** @return bytes read from the stream so far */
    public long bytesRead() {
        return bytesRead;
    }

    /** @return complete messages read so far */
    public long messages() {
        return messages;
    }

    /**
     * Reads until one message is complete.
     *
     * @param in the stream
     * @return the message's header; its body is {@link #body()} until the next call
     * @throws EOFException if the stream ended between two messages (the peer closed)
     * @throws PlayerProtocolException if the header is invalid or the stream ended inside a
     *     message
     * @throws java.net.SocketTimeoutException if the stream timed out; call again to resume
     * @throws IOException if the stream fails
     */
    public PlayerHeader read(InputStream in) throws IOException {
        if (broken != null) {
            throw broken;
        }
        if (complete) {
            frameStart += frameBytes;
            filled = 0;
            frameBytes = PlayerHeader.SIZE_BYTES;
            header = null;
            complete = false;
        }
        fill(in, PlayerHeader.SIZE_BYTES);
        if (header == null) {
            try {
                PlayerHeader h = PlayerHeader.decode(reader.reset(buf, 0, PlayerHeader.SIZE_BYTES, frameStart));
                if (h.size() > maxBodyBytes) {
                    throw new PlayerProtocolException(frameStart + PlayerHeader.SIZE_FIELD_OFFSET, "header.size",
                            "body size " + h.size() + " above the limit of " + maxBodyBytes + " bytes");
                }
                header = h;
            } catch (PlayerProtocolException e) {
                broken = e;
                throw e;
            }
            frameBytes = PlayerHeader.SIZE_BYTES + header.size();
            if (buf.length < frameBytes) {
                buf = Arrays.copyOf(buf, Math.max(frameBytes, Math.min(buf.length * 2, maxBodyBytes + 40)));
            }
        }
        fill(in, frameBytes);
        complete = true;
        messages++;
        return header;
    }

    private void fill(InputStream in, int target) throws IOException {
        while (filled < target) {
            int n = in.read(buf, filled, target - filled);
            if (n < 0) {
                if (filled == 0) {
                    throw new EOFException("connection closed by the peer at stream offset " + frameStart);
                }
                broken = new PlayerProtocolException(frameStart + filled,
                        header == null ? "header" : "body of " + header,
                        "stream ended after " + filled + " of " + target + " bytes of the message");
                throw broken;
            }
            filled += n;
            bytesRead += n;
        }
    }

    /**
     * @return a reader over the body of the message {@link #read} returned last
     * @throws IllegalStateException if no message is complete
     */
    public XdrReader body() {
        if (!complete) {
            throw new IllegalStateException("no complete message");
        }
        return reader.reset(buf, PlayerHeader.SIZE_BYTES, header.size(), frameStart + PlayerHeader.SIZE_BYTES);
    }

    /**
     * @return a copy of the raw bytes (header and body) of the message {@link #read} returned
     *     last (allocates; for tools, tests and relays)
     * @throws IllegalStateException if no message is complete
     */
    public byte[] copyMessage() {
        if (!complete) {
            throw new IllegalStateException("no complete message");
        }
        return Arrays.copyOf(buf, frameBytes);
    }

    /** @return the stream offset of the message {@link #read} returned last */
    public long messageOffset() {
        return frameStart;
    }
}
