package io.rtaware.record.encode;

import java.util.Arrays;

/**
 * A growable byte buffer that only grows, so that once at its working size appending allocates
 * nothing. Not thread-safe.
 */
public final class ByteBuf {

    private byte[] bytes;
    private int size;

    /** @param initialCapacity starting capacity in bytes */
    public ByteBuf(int initialCapacity) {
        bytes = new byte[Math.max(16, initialCapacity)];
    }

    /** @return the backing array; valid bytes are {@code [0, size())} */
    public byte[] array() {
        return bytes;
    }

    /** @return bytes held */
    public int size() {
        return size;
    }

    /** Empties the buffer (keeps its capacity). */
    public void clear() {
        size = 0;
    }

    /**
     * Makes room for {@code more} bytes.
     *
     * @param more bytes about to be appended
     */
    public void ensure(int more) {
        if (more > bytes.length - size) {
            bytes = Arrays.copyOf(bytes, Math.max(bytes.length * 2, size + more));
        }
    }

    /** @param b one byte */
    public void put(int b) {
        ensure(1);
        bytes[size++] = (byte) b;
    }

    /**
     * @param src bytes
     * @param offset first
     * @param length count
     */
    public void put(byte[] src, int offset, int length) {
        ensure(length);
        System.arraycopy(src, offset, bytes, size, length);
        size += length;
    }

    /** @param ascii ASCII text, appended byte per char */
    public void putAscii(CharSequence ascii) {
        int n = ascii.length();
        ensure(n);
        for (int i = 0; i < n; i++) {
            bytes[size++] = (byte) ascii.charAt(i);
        }
    }

    /** Sets the size after writing directly into {@link #array()} (after {@link #ensure}). */
    void size(int newSize) {
        size = newSize;
    }
}
