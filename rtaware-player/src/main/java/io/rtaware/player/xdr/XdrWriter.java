package io.rtaware.player.xdr;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * Encodes XDR items into a growable byte buffer that is kept between messages: after
 * {@link #reset()} the same array is written again, so steady-state encoding does not
 * allocate. Not thread-safe.
 */
public final class XdrWriter {

    private byte[] buf;
    private int pos;

    /** A writer with a 2 KiB initial buffer. */
    public XdrWriter() {
        this(2048);
    }

    /** @param initialCapacity initial buffer size in bytes */
    public XdrWriter(int initialCapacity) {
        buf = new byte[Math.max(64, initialCapacity)];
    }

    /**
     * Forgets what was written; keeps the buffer.
     *
     * @return this writer
     */
    public XdrWriter reset() {
        pos = 0;
        return this;
    }

    /** @return the buffer; bytes {@code 0..size()-1} are the encoding */
    public byte[] array() {
        return buf;
    }

    /** @return bytes written since the last reset */
    public int size() {
        return pos;
    }

    /** @return a copy of the bytes written (allocates; for tests and tools) */
    public byte[] toByteArray() {
        return Arrays.copyOf(buf, pos);
    }

    private void ensure(int more) {
        if (buf.length - pos < more) {
            buf = Arrays.copyOf(buf, Math.max(buf.length * 2, pos + more));
        }
    }

    /**
     * @param v a 32-bit integer (signed or unsigned; the low 32 bits are written)
     * @return this writer
     */
    public XdrWriter writeInt(long v) {
        ensure(4);
        pos += 4;
        putInt(pos - 4, (int) v);
        return this;
    }

    /**
     * Overwrites 4 bytes already written (e.g. a header's size field).
     *
     * @param at byte position, at most {@code size() - 4}
     * @param v the value
     * @throws IllegalArgumentException if the 4 bytes were not written yet
     */
    public void putInt(int at, int v) {
        if (at < 0 || at > pos - 4) {
            throw new IllegalArgumentException("position " + at + " outside the buffer");
        }
        buf[at] = (byte) (v >>> 24);
        buf[at + 1] = (byte) (v >>> 16);
        buf[at + 2] = (byte) (v >>> 8);
        buf[at + 3] = (byte) v;
    }

    /**
     * @param v a 64-bit integer
     * @return this writer
     */
    public XdrWriter writeLong(long v) {
        writeInt(v >>> 32);
        return writeInt(v);
    }

    /**
     * @param v a single-precision value
     * @return this writer
     */
    public XdrWriter writeFloat(float v) {
        return writeInt(Float.floatToRawIntBits(v));
    }

    /**
     * @param v a double-precision value
     * @return this writer
     */
    public XdrWriter writeDouble(double v) {
        return writeLong(Double.doubleToRawLongBits(v));
    }

    /**
     * Writes {@code xdr_bytes}: length, bytes, zero padding to a multiple of 4.
     *
     * @param data source
     * @param offset first byte
     * @param length number of bytes
     * @return this writer
     */
    public XdrWriter writeBytes(byte[] data, int offset, int length) {
        writeInt(length);
        int padded = XdrReader.padded(length);
        ensure(padded);
        System.arraycopy(data, offset, buf, pos, length);
        Arrays.fill(buf, pos + length, pos + padded, (byte) 0);
        pos += padded;
        return this;
    }

    /**
     * Writes a C string the way Player does: the struct's {@code _count} (length including
     * the terminating NUL, or 0 for an empty string) followed by {@code xdr_bytes} of the same
     * bytes.
     *
     * @param s the text (ISO-8859-1); empty writes count 0 and an empty byte string
     * @return this writer
     */
    public XdrWriter writeCountedString(String s) {
        byte[] bytes = s.isEmpty() ? new byte[0] : (s + '\0').getBytes(StandardCharsets.ISO_8859_1);
        writeInt(bytes.length);
        return writeBytes(bytes, 0, bytes.length);
    }
}
