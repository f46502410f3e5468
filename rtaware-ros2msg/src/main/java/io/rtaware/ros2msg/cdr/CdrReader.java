package io.rtaware.ros2msg.cdr;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;

/**
 * Reads one CDR message (XCDR1, little endian) from a byte range, checking every length against
 * what is left before using it: a sequence or string longer than the rest of the buffer is
 * rejected with {@link CdrException} before anything is allocated or copied. Reuse one reader by
 * calling {@link #wrap} for each message; reading allocates nothing (strings are appended to a
 * caller's {@link StringBuilder}). Not thread-safe.
 */
public final class CdrReader {

    private static final VarHandle I16 = MethodHandles.byteArrayViewVarHandle(short[].class, ByteOrder.LITTLE_ENDIAN);
    private static final VarHandle I32 = MethodHandles.byteArrayViewVarHandle(int[].class, ByteOrder.LITTLE_ENDIAN);
    private static final VarHandle I64 = MethodHandles.byteArrayViewVarHandle(long[].class, ByteOrder.LITTLE_ENDIAN);

    private byte[] data = new byte[0];
    private int origin;
    private int position;
    private int limit;

    /**
     * Starts reading a message and checks its encapsulation header.
     *
     * @param bytes the buffer
     * @param offset where the message starts
     * @param length the message's length in bytes
     * @return this reader
     * @throws CdrException if the range is invalid, shorter than the header, or not CDR little endian
     */
    public CdrReader wrap(byte[] bytes, int offset, int length) {
        if (offset < 0 || length < 0 || offset > bytes.length - length) {
            throw new CdrException("CDR range " + offset + "+" + length + " outside a buffer of " + bytes.length);
        }
        if (length < CdrWriter.HEADER_BYTES) {
            throw new CdrException("CDR message of " + length + " bytes is shorter than its 4-byte header");
        }
        if (bytes[offset] != 0 || bytes[offset + 1] != 1) {
            throw new CdrException(String.format("unsupported CDR encapsulation %02x %02x (only 00 01, CDR little endian)",
                    bytes[offset], bytes[offset + 1]));
        }
        this.data = bytes;
        this.origin = offset + CdrWriter.HEADER_BYTES;
        this.position = origin;
        this.limit = offset + length;
        return this;
    }

    /** @return bytes not yet read */
    public int remaining() {
        return limit - position;
    }

    private void need(int bytes, String what) {
        if (bytes > limit - position) {
            throw new CdrException("CDR message truncated: " + what + " needs " + bytes + " bytes, "
                    + (limit - position) + " left");
        }
    }

    /** @param alignment 1, 2, 4 or 8: skips padding counted from the end of the header */
    public void align(int alignment) {
        int pad = (alignment - ((position - origin) & (alignment - 1))) & (alignment - 1);
        need(pad, "padding");
        position += pad;
    }

    /** @return an int8 (or a byte/char; mask with 0xff for uint8) */
    public byte readInt8() {
        need(1, "int8");
        return data[position++];
    }

    /** @return a bool */
    public boolean readBool() {
        return readInt8() != 0;
    }

    /** @return an int16 */
    public short readInt16() {
        align(2);
        need(2, "int16");
        short v = (short) I16.get(data, position);
        position += 2;
        return v;
    }

    /** @return an int32 (a uint32 as its bit pattern) */
    public int readInt32() {
        align(4);
        need(4, "int32");
        int v = (int) I32.get(data, position);
        position += 4;
        return v;
    }

    /** @return an int64 */
    public long readInt64() {
        align(8);
        need(8, "int64");
        long v = (long) I64.get(data, position);
        position += 8;
        return v;
    }

    /** @return a float32 */
    public float readFloat32() {
        return Float.intBitsToFloat(readInt32());
    }

    /** @return a float64 */
    public double readFloat64() {
        return Double.longBitsToDouble(readInt64());
    }

    /**
     * Reads a sequence's element count and checks that that many elements can still be in the
     * buffer.
     *
     * @param minElementBytes the least number of bytes one element takes on the wire (1 or more)
     * @return the count
     * @throws CdrException if the count exceeds what the rest of the buffer can hold
     */
    public int readSequenceLength(int minElementBytes) {
        long count = readInt32() & 0xffffffffL;
        if (count * minElementBytes > limit - position) {
            throw new CdrException("CDR sequence of " + count + " elements exceeds the " + (limit - position)
                    + " bytes left in the message");
        }
        return (int) count;
    }

    /**
     * Reads a string and appends it to {@code into} (which is not cleared).
     *
     * @param into receives the text
     * @throws CdrException if the length exceeds the buffer or the string is not NUL-terminated
     */
    public void readString(StringBuilder into) {
        int n = readStringLength();
        boolean ascii = true;
        for (int i = 0; i < n - 1 && ascii; i++) {
            ascii = data[position + i] >= 0;
        }
        if (ascii) {
            for (int i = 0; i < n - 1; i++) {
                into.append((char) data[position + i]);
            }
        } else {
            into.append(new String(data, position, n - 1, StandardCharsets.UTF_8));
        }
        position += n;
    }

    /** Skips a string. */
    public void skipString() {
        int n = readStringLength();
        position += n;
    }

    private int readStringLength() {
        long n = readInt32() & 0xffffffffL;
        if (n < 1 || n > limit - position) {
            throw new CdrException("CDR string length " + n + " invalid with " + (limit - position) + " bytes left");
        }
        if (data[position + (int) n - 1] != 0) {
            throw new CdrException("CDR string of length " + n + " is not NUL-terminated");
        }
        return (int) n;
    }

    /**
     * Skips bytes (the content of an int8 sequence, for example).
     *
     * @param bytes how many
     */
    public void skip(int bytes) {
        need(bytes, "skipped field");
        position += bytes;
    }

    /**
     * Copies bytes (the content of an int8 or uint8 sequence).
     *
     * @param into destination
     * @param offset where to put the first byte
     * @param count how many
     */
    public void readBytes(byte[] into, int offset, int count) {
        need(count, "byte sequence");
        System.arraycopy(data, position, into, offset, count);
        position += count;
    }
}
