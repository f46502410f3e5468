package io.rtaware.record.mcap;

import java.io.IOException;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.file.Path;

/** What every part of the reader shares: little-endian fields of a byte array, positioned reads, errors that name the byte. */
final class McapBytes {

    /** The largest record or decompressed chunk, bytes ({@link McapReader#MAX_RECORD_MIB}). */
    static final long MAX_RECORD_BYTES = (long) McapReader.MAX_RECORD_MIB << 20;
    /** Opcode and length that start every record. */
    static final int RECORD_HEAD = 1 + 8;
    /** Footer record: opcode, length, summary start, summary offset start, CRC. */
    static final int FOOTER_BYTES = 1 + 8 + 8 + 8 + 4;
    /** Data-end record: opcode, length, CRC. */
    static final int DATA_END_BYTES = 1 + 8 + 4;

    static final VarHandle I16 = MethodHandles.byteArrayViewVarHandle(short[].class, ByteOrder.LITTLE_ENDIAN);
    static final VarHandle I32 = MethodHandles.byteArrayViewVarHandle(int[].class, ByteOrder.LITTLE_ENDIAN);
    static final VarHandle I64 = MethodHandles.byteArrayViewVarHandle(long[].class, ByteOrder.LITTLE_ENDIAN);

    private McapBytes() {
    }

    static long u64(byte[] b, int at) {
        return (long) I64.get(b, at);
    }

    static long u32(byte[] b, int at) {
        return (int) I32.get(b, at) & 0xffffffffL;
    }

    /** Reads exactly {@code n} bytes at {@code position}; false if the file ends first. */
    static boolean readFully(FileChannel ch, long position, byte[] into, int offset, int n) throws IOException {
        ByteBuffer buffer = ByteBuffer.wrap(into, offset, n);
        long at = position;
        while (buffer.hasRemaining()) {
            int got = ch.read(buffer, at);
            if (got < 0) {
                return false;
            }
            at += got;
        }
        return true;
    }

    /** @return one line naming the file, the problem and the byte */
    static McapFormatException error(Path file, long at, String what) {
        return new McapFormatException(file + ": " + what + " at byte " + at);
    }
}
