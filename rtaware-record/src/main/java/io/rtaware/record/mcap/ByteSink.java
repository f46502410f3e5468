package io.rtaware.record.mcap;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.Map;

/**
 * A growable little-endian byte buffer for building MCAP records. It only grows (doubling), so
 * once it has reached a run's largest size, appending allocates nothing. Not thread-safe.
 */
final class ByteSink {

    private static final VarHandle I16 = MethodHandles.byteArrayViewVarHandle(short[].class, ByteOrder.LITTLE_ENDIAN);
    private static final VarHandle I32 = MethodHandles.byteArrayViewVarHandle(int[].class, ByteOrder.LITTLE_ENDIAN);
    private static final VarHandle I64 = MethodHandles.byteArrayViewVarHandle(long[].class, ByteOrder.LITTLE_ENDIAN);

    private byte[] bytes;
    private int size;

    ByteSink(int initialCapacity) {
        bytes = new byte[Math.max(16, initialCapacity)];
    }

    byte[] array() {
        return bytes;
    }

    int size() {
        return size;
    }

    void clear() {
        size = 0;
    }

    void ensure(int more) {
        if (more > bytes.length - size) {
            long wanted = Math.max((long) bytes.length * 2, (long) size + more);
            if (wanted > Integer.MAX_VALUE - 16) {
                throw new IllegalStateException("MCAP record over 2 GB");
            }
            bytes = Arrays.copyOf(bytes, (int) wanted);
        }
    }

    void u8(int v) {
        ensure(1);
        bytes[size++] = (byte) v;
    }

    void u16(int v) {
        ensure(2);
        I16.set(bytes, size, (short) v);
        size += 2;
    }

    void u32(long v) {
        ensure(4);
        I32.set(bytes, size, (int) v);
        size += 4;
    }

    void u64(long v) {
        ensure(8);
        I64.set(bytes, size, v);
        size += 8;
    }

    /** Overwrites a uint64 written earlier (a record length). */
    void u64At(int at, long v) {
        I64.set(bytes, at, v);
    }

    void bytes(byte[] src, int offset, int length) {
        ensure(length);
        System.arraycopy(src, offset, bytes, size, length);
        size += length;
    }

    /** An MCAP string: uint32 byte length, UTF-8 bytes. */
    void string(String s) {
        byte[] utf8 = s.getBytes(StandardCharsets.UTF_8);
        u32(utf8.length);
        bytes(utf8, 0, utf8.length);
    }

    /** An MCAP {@code Map<string, string>}: uint32 byte length, then key/value strings. */
    void stringMap(Map<String, String> map) {
        int lengthAt = size;
        u32(0);
        for (Map.Entry<String, String> e : map.entrySet()) {
            string(e.getKey());
            string(e.getValue());
        }
        I32.set(bytes, lengthAt, size - lengthAt - 4);
    }

    /** Starts a record: opcode and a length placeholder; returns where the content starts. */
    int beginRecord(int opcode) {
        u8(opcode);
        u64(0);
        return size;
    }

    /** Fills in the length of the record whose content started at {@code contentStart}. */
    void endRecord(int contentStart) {
        u64At(contentStart - 8, size - contentStart);
    }
}
