package io.rtaware.ros2msg.cdr;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;

/**
 * Writes one CDR message (XCDR1, little endian) into a byte array allocated once. Call
 * {@link #begin()} for each message, then the field writers in declaration order; the message
 * is {@code buffer()[0 .. size())}. Writing past the capacity throws {@link CdrException}.
 * Allocates nothing except when a string holds characters outside ASCII. Not thread-safe.
 */
public final class CdrWriter {

    /** Length of the encapsulation header in bytes. */
    public static final int HEADER_BYTES = 4;

    private static final VarHandle I16 = MethodHandles.byteArrayViewVarHandle(short[].class, ByteOrder.LITTLE_ENDIAN);
    private static final VarHandle I32 = MethodHandles.byteArrayViewVarHandle(int[].class, ByteOrder.LITTLE_ENDIAN);
    private static final VarHandle I64 = MethodHandles.byteArrayViewVarHandle(long[].class, ByteOrder.LITTLE_ENDIAN);

    private final byte[] buffer;
    private int position;

    /** @param capacityBytes the largest message this writer can hold, header included */
    public CdrWriter(int capacityBytes) {
        if (capacityBytes < HEADER_BYTES) {
            throw new IllegalArgumentException("CDR capacity " + capacityBytes + " below the 4-byte header");
        }
        this.buffer = new byte[capacityBytes];
    }

    /**
     * Starts a new message: writes the encapsulation header (CDR, little endian).
     *
     * @return this writer
     */
    public CdrWriter begin() {
        buffer[0] = 0;
        buffer[1] = 1;
        buffer[2] = 0;
        buffer[3] = 0;
        position = HEADER_BYTES;
        return this;
    }

    /** @return the buffer holding the message; valid bytes are {@code [0, size())} */
    public byte[] buffer() {
        return buffer;
    }

    /** @return bytes written so far, header included */
    public int size() {
        return position;
    }

    /** @return the capacity in bytes */
    public int capacity() {
        return buffer.length;
    }

    private void ensure(int bytes) {
        if (bytes > buffer.length - position) {
            throw new CdrException("CDR message exceeds the writer's capacity of " + buffer.length + " bytes");
        }
    }

    /**
     * Pads with zeros to a multiple of {@code alignment} counted from the end of the header.
     *
     * @param alignment 1, 2, 4 or 8
     */
    public void align(int alignment) {
        int pad = (alignment - ((position - HEADER_BYTES) & (alignment - 1))) & (alignment - 1);
        ensure(pad);
        for (int i = 0; i < pad; i++) {
            buffer[position++] = 0;
        }
    }

    /** @param v a byte, char, int8, uint8 or bool (as 0/1) */
    public void writeInt8(int v) {
        ensure(1);
        buffer[position++] = (byte) v;
    }

    /** @param v a boolean */
    public void writeBool(boolean v) {
        writeInt8(v ? 1 : 0);
    }

    /** @param v an int16 or uint16 */
    public void writeInt16(int v) {
        align(2);
        ensure(2);
        I16.set(buffer, position, (short) v);
        position += 2;
    }

    /** @param v an int32 or uint32 */
    public void writeInt32(int v) {
        align(4);
        ensure(4);
        I32.set(buffer, position, v);
        position += 4;
    }

    /** @param v an int64 or uint64 */
    public void writeInt64(long v) {
        align(8);
        ensure(8);
        I64.set(buffer, position, v);
        position += 8;
    }

    /** @param v a float32 */
    public void writeFloat32(float v) {
        writeInt32(Float.floatToRawIntBits(v));
    }

    /** @param v a float64 */
    public void writeFloat64(double v) {
        writeInt64(Double.doubleToRawLongBits(v));
    }

    /**
     * Writes the element count of a sequence ({@code uint32}).
     *
     * @param count elements that follow
     */
    public void writeSequenceLength(int count) {
        if (count < 0) {
            throw new CdrException("negative sequence length " + count);
        }
        writeInt32(count);
    }

    /**
     * Writes a string: uint32 length including the terminating NUL, the UTF-8 bytes, the NUL.
     *
     * @param s the text (null is written as the empty string)
     */
    public void writeString(CharSequence s) {
        int n = s == null ? 0 : s.length();
        boolean ascii = true;
        for (int i = 0; i < n && ascii; i++) {
            ascii = s.charAt(i) < 0x80;
        }
        if (!ascii) {
            byte[] utf8 = s.toString().getBytes(StandardCharsets.UTF_8);
            writeInt32(utf8.length + 1);
            ensure(utf8.length + 1);
            System.arraycopy(utf8, 0, buffer, position, utf8.length);
            position += utf8.length;
            buffer[position++] = 0;
            return;
        }
        writeInt32(n + 1);
        ensure(n + 1);
        for (int i = 0; i < n; i++) {
            buffer[position++] = (byte) s.charAt(i);
        }
        buffer[position++] = 0;
    }

    /**
     * Writes a {@code float32[]} sequence: its length, then the values.
     *
     * @param values source
     * @param offset first value
     * @param count number of values
     */
    public void writeFloat32Sequence(float[] values, int offset, int count) {
        writeSequenceLength(count);
        for (int i = 0; i < count; i++) {
            writeFloat32(values[offset + i]);
        }
    }

    /**
     * Writes an {@code int8[]} or {@code uint8[]} sequence: its length, then the bytes.
     *
     * @param values source
     * @param offset first byte
     * @param count number of bytes
     */
    public void writeInt8Sequence(byte[] values, int offset, int count) {
        writeSequenceLength(count);
        ensure(count);
        System.arraycopy(values, offset, buffer, position, count);
        position += count;
    }

    /**
     * Writes a fixed-size array of float64 with one value repeated (e.g. a zero covariance).
     *
     * @param value the value
     * @param count the array's size
     */
    public void writeFloat64Repeated(double value, int count) {
        for (int i = 0; i < count; i++) {
            writeFloat64(value);
        }
    }
}
