package io.rtaware.player.xdr;

import java.io.IOException;

/**
 * The bytes received do not form a valid Player message: a truncated or corrupt body, a header
 * whose size is negative or above the configured limit, or a peer that is not a Player server.
 * The message names the byte offset in the stream (when known) and the field being decoded.
 * Immutable and thread-safe.
 */
public class PlayerProtocolException extends IOException {

    private static final long serialVersionUID = 1L;

    /** Byte offset where the problem was found; -1 if unknown. */
    private final long offset;
    /** The field being decoded, e.g. {@code laser.ranges}. */
    private final String field;

    /**
     * @param offset byte offset in the stream (or buffer) where the problem was found; -1 if
     *     unknown
     * @param field the field being decoded, e.g. {@code laser.ranges}
     * @param problem what is wrong, e.g. {@code needs 4 bytes, 2 left}
     */
    public PlayerProtocolException(long offset, String field, String problem) {
        super((offset >= 0 ? "at byte offset " + offset + ", " : "") + "field '" + field + "': " + problem);
        this.offset = offset;
        this.field = field;
    }

    /** @return the byte offset of the problem, or -1 if unknown */
    public long offset() {
        return offset;
    }

    /** @return the field being decoded when the problem was found */
    public String field() {
        return field;
    }
}
