package io.rtaware.player.protocol;

import io.rtaware.player.xdr.PlayerProtocolException;
import io.rtaware.player.xdr.XdrReader;
import io.rtaware.player.xdr.XdrWriter;

/**
 * The 40-byte message header ({@code player_msghdr_t}). In SYNCH messages from a real server
 * {@code timestampS} and {@code seq} are uninitialised memory and must be ignored. Server
 * timestamps are the server's clock (simulated seconds with Stage). Immutable and
 * thread-safe.
 *
 * @param host device host (unsigned 32 bits)
 * @param robot device robot, i.e. server port (unsigned 32 bits)
 * @param interf interface code
 * @param index device index
 * @param type message type, see {@link MessageType}
 * @param subtype interface-specific subtype
 * @param timestampS timestamp in seconds
 * @param seq sequence number (unsigned 32 bits; 0 over TCP)
 * @param size body length in bytes
 */
public record PlayerHeader(long host, long robot, int interf, int index, int type, int subtype,
                           double timestampS, long seq, int size) {

    /** Encoded size in bytes. */
    public static final int SIZE_BYTES = 40;
    /** Byte offset of the size field inside the header. */
    public static final int SIZE_FIELD_OFFSET = 36;

    /**
     * Decodes a header. The size is checked by the caller against its limit (see
     * {@link PlayerFrameReader}); here only its sign is checked.
     *
     * @param r reader positioned at the header
     * @return the header
     * @throws PlayerProtocolException if fewer than 40 bytes are left or the size is negative
     */
    public static PlayerHeader decode(XdrReader r) throws PlayerProtocolException {
        long host = r.readUnsignedInt("header.host");
        long robot = r.readUnsignedInt("header.robot");
        int interf = r.readU16("header.interf");
        int index = r.readU16("header.index");
        int type = r.readU8("header.type");
        int subtype = r.readU8("header.subtype");
        double ts = r.readDouble("header.timestamp");
        long seq = r.readUnsignedInt("header.seq");
        long at = r.streamPosition();
        int size = r.readInt("header.size");
        if (size < 0) {
            throw new PlayerProtocolException(at, "header.size", "body size " + (size & 0xffffffffL)
                    + " is negative as a signed 32-bit integer");
        }
        return new PlayerHeader(host, robot, interf, index, type, subtype, ts, seq, size);
    }

    /**
     * Encodes this header as is (including {@link #size}).
     *
     * @param w destination
     */
    public void encode(XdrWriter w) {
        w.writeInt(host).writeInt(robot).writeInt(interf).writeInt(index).writeInt(type).writeInt(subtype)
                .writeDouble(timestampS).writeInt(seq).writeInt(size);
    }

    /** @return the device address of this message */
    public DeviceAddress address() {
        return new DeviceAddress(host, robot, interf, index);
    }

    /**
     * @param interfCode interface code
     * @param deviceIndex device index
     * @param msgType message type
     * @param msgSubtype subtype
     * @return true if this header has exactly these four fields
     */
    public boolean is(int interfCode, int deviceIndex, int msgType, int msgSubtype) {
        return interf == interfCode && index == deviceIndex && type == msgType && subtype == msgSubtype;
    }

    /** @return e.g. {@code RESP_ACK laser:0 subtype 3 (28 bytes)} */
    @Override
    public String toString() {
        return MessageType.name(type) + " " + Interfaces.name(interf) + ":" + index + " subtype " + subtype
                + " (" + size + " bytes, t=" + timestampS + ")";
    }
}
