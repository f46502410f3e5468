package io.rtaware.player.xdr;

import java.nio.charset.StandardCharsets;

/**
 * Decodes XDR items from a region of a byte array without copying it. Every read checks that
 * the item fits in the region and throws {@link PlayerProtocolException} naming the absolute
 * byte offset (region start plus {@link #baseOffset()}) and the field otherwise; no read can
 * cause an out-of-bounds access or an allocation larger than the region. One instance is
 * meant to be {@link #reset reset} for every message. Not thread-safe.
 */
public final class XdrReader {

    private byte[] buf = new byte[0];
    private int start;
    private int pos;
    private int limit;
    private long baseOffset;

    /** A reader over an empty region; call {@link #reset} before reading. */
    public XdrReader() {
    }

    /**
     * @param data the bytes to decode
     * @param offset first byte of the region
     * @param length region length in bytes
     */
    public XdrReader(byte[] data, int offset, int length) {
        reset(data, offset, length, 0);
    }

    /**
     * Points this reader at a new region.
     *
     * @param data the bytes to decode (not copied; must not change while reading)
     * @param offset first byte of the region
     * @param length region length in bytes
     * @param streamOffset the position of {@code data[offset]} in the stream, used in error
     *     messages
     * @return this reader
     * @throws IllegalArgumentException if the region lies outside {@code data}
     */
    public XdrReader reset(byte[] data, int offset, int length, long streamOffset) {
        if (offset < 0 || length < 0 || offset > data.length - length) {
            throw new IllegalArgumentException("region " + offset + "+" + length + " outside array of " + data.length);
        }
        this.buf = data;
        this.start = offset;
        this.pos = offset;
        this.limit = offset + length;
        this.baseOffset = streamOffset;
        return this;
    }

    /** @return the array this reader reads from (not a copy) */
    public byte[] array() {
        return buf;
    }

    /** @return the index in {@link #array()} of the region's first byte */
    public int start() {
        return start;
    }

    /** @return the stream position of the region's first byte */
    public long baseOffset() {
        return baseOffset;
    }

    /** @return the stream position of the next byte to read */
    public long streamPosition() {
        return baseOffset + (pos - start);
    }

    /** @return bytes left in the region */
    public int remaining() {
        return limit - pos;
    }

    /** @return bytes read from the region so far */
    public int consumed() {
        return pos - start;
    }

    private void need(int bytes, String field) throws PlayerProtocolException {
        if (limit - pos < bytes) {
            throw new PlayerProtocolException(streamPosition(), field,
                    "needs " + bytes + " bytes, only " + (limit - pos) + " left in the message");
        }
    }

    private int rawInt() {
        int v = ((buf[pos] & 0xff) << 24) | ((buf[pos + 1] & 0xff) << 16) | ((buf[pos + 2] & 0xff) << 8)
                | (buf[pos + 3] & 0xff);
        pos += 4;
        return v;
    }

    /**
     * @param field field name for errors
     * @return a signed 32-bit integer
     * @throws PlayerProtocolException if fewer than 4 bytes are left
     */
    public int readInt(String field) throws PlayerProtocolException {
        need(4, field);
        return rawInt();
    }

    /**
     * @param field field name for errors
     * @return an unsigned 32-bit integer
     * @throws PlayerProtocolException if fewer than 4 bytes are left
     */
    public long readUnsignedInt(String field) throws PlayerProtocolException {
        return readInt(field) & 0xffffffffL;
    }

    /**
     * Reads a {@code uint8_t} (4 bytes on the wire); like Player's decoder it keeps the low 8
     * bits.
     *
     * @param field field name for errors
     * @return 0..255
     * @throws PlayerProtocolException if fewer than 4 bytes are left
     */
    public int readU8(String field) throws PlayerProtocolException {
        return readInt(field) & 0xff;
    }

    /**
     * Reads a {@code uint16_t} (4 bytes on the wire), keeping the low 16 bits.
     *
     * @param field field name for errors
     * @return 0..65535
     * @throws PlayerProtocolException if fewer than 4 bytes are left
     */
    public int readU16(String field) throws PlayerProtocolException {
        return readInt(field) & 0xffff;
    }

    /**
     * @param field field name for errors
     * @return a signed 64-bit integer
     * @throws PlayerProtocolException if fewer than 8 bytes are left
     */
    public long readLong(String field) throws PlayerProtocolException {
        need(8, field);
        long hi = rawInt() & 0xffffffffL;
        long lo = rawInt() & 0xffffffffL;
        return (hi << 32) | lo;
    }

    /**
     * @param field field name for errors
     * @return an IEEE 754 single
     * @throws PlayerProtocolException if fewer than 4 bytes are left
     */
    public float readFloat(String field) throws PlayerProtocolException {
        return Float.intBitsToFloat(readInt(field));
    }

    /**
     * @param field field name for errors
     * @return an IEEE 754 double
     * @throws PlayerProtocolException if fewer than 8 bytes are left
     */
    public double readDouble(String field) throws PlayerProtocolException {
        return Double.longBitsToDouble(readLong(field));
    }

    /**
     * Reads an array element count and checks that that many elements can still follow.
     *
     * @param field field name for errors
     * @param elementBytes the encoded size of one element (at least 1)
     * @param maxCount the largest count the caller accepts (e.g. its buffer's capacity)
     * @return the count, 0..maxCount
     * @throws PlayerProtocolException if the count is negative as a signed int, above
     *     {@code maxCount}, or larger than the remaining bytes allow
     */
    public int readCount(String field, int elementBytes, int maxCount) throws PlayerProtocolException {
        long at = streamPosition();
        int count = readInt(field);
        if (count < 0 || count > maxCount) {
            throw new PlayerProtocolException(at, field, "count " + (count & 0xffffffffL) + " outside 0.." + maxCount);
        }
        if ((long) count * elementBytes > remaining()) {
            throw new PlayerProtocolException(at, field, "count " + count + " needs " + (long) count * elementBytes
                    + " bytes, only " + remaining() + " left in the message");
        }
        return count;
    }

    /**
     * Reads a variable byte string ({@code xdr_bytes}): length, bytes, 0-3 pad bytes.
     *
     * @param field field name for errors
     * @param dest where to copy the bytes
     * @return the number of bytes copied
     * @throws PlayerProtocolException if the length is negative, exceeds {@code dest.length}
     *     or the remaining bytes
     */
    public int readBytes(String field, byte[] dest) throws PlayerProtocolException {
        int n = readCount(field, 1, dest.length);
        int padded = padded(n);
        need(padded, field);
        System.arraycopy(buf, pos, dest, 0, n);
        pos += padded;
        return n;
    }

    /**
     * Reads a variable byte string ({@code xdr_bytes}) as text, dropping trailing NULs (Player
     * counts a driver name's terminating NUL).
     *
     * @param field field name for errors
     * @param maxBytes the largest length accepted
     * @return the text (ISO-8859-1, so every byte maps to one character)
     * @throws PlayerProtocolException if the length is negative, above {@code maxBytes} or
     *     the remaining bytes
     */
    public String readString(String field, int maxBytes) throws PlayerProtocolException {
        int n = readCount(field, 1, maxBytes);
        int padded = padded(n);
        need(padded, field);
        int end = n;
        while (end > 0 && buf[pos + end - 1] == 0) {
            end--;
        }
        String s = new String(buf, pos, end, StandardCharsets.ISO_8859_1);
        pos += padded;
        return s;
    }

    /**
     * Skips bytes.
     *
     * @param field field name for errors
     * @param bytes how many
     * @throws PlayerProtocolException if fewer are left
     */
    public void skip(String field, int bytes) throws PlayerProtocolException {
        need(bytes, field);
        pos += bytes;
    }

    /**
     * Checks that the whole region was consumed.
     *
     * @param what the message being decoded, for errors
     * @throws PlayerProtocolException if bytes are left over
     */
    public void expectEnd(String what) throws PlayerProtocolException {
        if (pos != limit) {
            throw new PlayerProtocolException(streamPosition(), what, (limit - pos) + " unexpected trailing bytes");
        }
    }

    /**
     * @param n a length in bytes
     * @return {@code n} rounded up to a multiple of 4
     */
    public static int padded(int n) {
        return (n + 3) & ~3;
    }
}
