package io.rtaware.record.mcap;

import com.github.luben.zstd.Zstd;
import java.io.IOException;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.zip.CRC32;

/**
 * Reads MCAP files: every record of the data section in file order (chunks decompressed and
 * their CRC checked, the data section's CRC checked at the data-end record), and the summary
 * (its CRC checked). Every length read from the file is checked against what is left before it
 * is used. Reads the whole file into memory (files up to 2 GB). Supports uncompressed and zstd
 * chunks.
 */
public final class McapReader {

    private static final VarHandle I16 = MethodHandles.byteArrayViewVarHandle(short[].class, ByteOrder.LITTLE_ENDIAN);
    private static final VarHandle I32 = MethodHandles.byteArrayViewVarHandle(int[].class, ByteOrder.LITTLE_ENDIAN);
    private static final VarHandle I64 = MethodHandles.byteArrayViewVarHandle(long[].class, ByteOrder.LITTLE_ENDIAN);
    /** Footer record: opcode, length, summary start, summary offset start, CRC. */
    private static final int FOOTER_BYTES = 1 + 8 + 8 + 8 + 4;

    private final Path path;
    private final byte[] bytes;

    private McapReader(Path path, byte[] bytes) {
        this.path = path;
        this.bytes = bytes;
    }

    /**
     * Loads a file and checks its leading and trailing magic.
     *
     * @param path the file
     * @return a reader
     * @throws IOException if it cannot be read or is not MCAP
     */
    public static McapReader open(Path path) throws IOException {
        byte[] bytes = Files.readAllBytes(path);
        McapReader reader = new McapReader(path, bytes);
        int m = Opcode.MAGIC.length;
        if (bytes.length < 2 * m + FOOTER_BYTES || !Arrays.equals(bytes, 0, m, Opcode.MAGIC, 0, m)) {
            throw reader.error(0, "not an MCAP file (no leading magic)");
        }
        if (!Arrays.equals(bytes, bytes.length - m, bytes.length, Opcode.MAGIC, 0, m)) {
            throw reader.error(bytes.length - m, "MCAP file not finished (no trailing magic)");
        }
        return reader;
    }

    /** @return the file's size in bytes */
    public long sizeBytes() {
        return bytes.length;
    }

    private McapFormatException error(long at, String what) {
        return new McapFormatException(path + ": " + what + " at byte " + at);
    }

    /** A bounded cursor over a byte range. */
    private final class Cursor {
        final byte[] data;
        int at;
        final int limit;

        Cursor(byte[] data, int from, int limit) {
            this.data = data;
            this.at = from;
            this.limit = limit;
        }

        void need(long n) throws McapFormatException {
            if (n < 0 || n > limit - at) {
                throw error(at, "record field of " + n + " bytes overruns its record (" + (limit - at) + " left)");
            }
        }

        int u8() throws McapFormatException {
            need(1);
            return data[at++] & 0xff;
        }

        int u16() throws McapFormatException {
            need(2);
            int v = (short) I16.get(data, at) & 0xffff;
            at += 2;
            return v;
        }

        long u32() throws McapFormatException {
            need(4);
            long v = (int) I32.get(data, at) & 0xffffffffL;
            at += 4;
            return v;
        }

        long u64() throws McapFormatException {
            need(8);
            long v = (long) I64.get(data, at);
            at += 8;
            return v;
        }

        String string() throws McapFormatException {
            long n = u32();
            need(n);
            String s = new String(data, at, (int) n, StandardCharsets.UTF_8);
            at += (int) n;
            return s;
        }

        Map<String, String> stringMap() throws McapFormatException {
            long n = u32();
            need(n);
            int end = at + (int) n;
            Map<String, String> map = new LinkedHashMap<>();
            Cursor inner = new Cursor(data, at, end);
            while (inner.at < end) {
                map.put(inner.string(), inner.string());
            }
            at = end;
            return map;
        }
    }

    /**
     * Hands every schema, channel, metadata and message record of the data section to the
     * visitor, in file order, checking chunk CRCs and the data section CRC.
     *
     * @param visitor receives the records
     * @throws IOException if the file is malformed or a CRC differs
     */
    public void read(McapVisitor visitor) throws IOException {
        Map<Integer, McapChannel> channels = new HashMap<>();
        Cursor c = new Cursor(bytes, Opcode.MAGIC.length, bytes.length);
        while (c.at < c.limit) {
            int recordStart = c.at;
            int opcode = c.u8();
            long length = c.u64();
            c.need(length);
            int end = c.at + (int) length;
            Cursor r = new Cursor(bytes, c.at, end);
            if (opcode == Opcode.DATA_END) {
                long crc = r.u32();
                if (crc != 0) {
                    CRC32 actual = new CRC32();
                    actual.update(bytes, 0, recordStart);
                    if (actual.getValue() != crc) {
                        throw error(recordStart, String.format("data section CRC %08x differs from the recorded %08x",
                                actual.getValue(), crc));
                    }
                }
                return;
            }
            if (opcode == Opcode.CHUNK) {
                readChunk(r, visitor, channels);
            } else {
                dispatch(opcode, r, visitor, channels);
            }
            c.at = end;
        }
        throw error(c.at, "MCAP data section has no data-end record");
    }

    private void dispatch(int opcode, Cursor r, McapVisitor visitor, Map<Integer, McapChannel> channels)
            throws McapFormatException {
        switch (opcode) {
            case Opcode.SCHEMA -> visitor.schema(schema(r));
            case Opcode.CHANNEL -> {
                McapChannel ch = channel(r);
                channels.put(ch.id(), ch);
                visitor.channel(ch);
            }
            case Opcode.METADATA -> visitor.metadata(r.string(), r.stringMap());
            case Opcode.MESSAGE -> {
                int channelId = r.u16();
                long sequence = r.u32();
                long logTime = r.u64();
                long publishTime = r.u64();
                McapChannel ch = channels.get(channelId);
                if (ch == null) {
                    throw error(r.at, "message on channel " + channelId + " before its channel record");
                }
                visitor.message(ch, sequence, logTime, publishTime, r.data, r.at, r.limit - r.at);
            }
            default -> {
                // header, indexes, attachments: nothing for the visitor
            }
        }
    }

    private McapSchema schema(Cursor r) throws McapFormatException {
        int id = r.u16();
        String name = r.string();
        String encoding = r.string();
        long n = r.u32();
        r.need(n);
        String data = new String(r.data, r.at, (int) n, StandardCharsets.UTF_8);
        return new McapSchema(id, name, encoding, data);
    }

    private McapChannel channel(Cursor r) throws McapFormatException {
        return new McapChannel(r.u16(), r.u16(), r.string(), r.string(), r.stringMap());
    }

    private void readChunk(Cursor r, McapVisitor visitor, Map<Integer, McapChannel> channels) throws IOException {
        int chunkStart = r.at;
        r.u64();
        r.u64();
        long uncompressedSize = r.u64();
        long crc = r.u32();
        String compression = r.string();
        long recordsLength = r.u64();
        r.need(recordsLength);
        if (uncompressedSize > Integer.MAX_VALUE - 16) {
            throw error(chunkStart, "chunk of " + uncompressedSize + " bytes uncompressed is too large");
        }
        byte[] records;
        int from;
        if (compression.isEmpty()) {
            if (uncompressedSize != recordsLength) {
                throw error(chunkStart, "uncompressed chunk sizes differ: " + uncompressedSize + " vs " + recordsLength);
            }
            records = r.data;
            from = r.at;
        } else if (compression.equals(Compression.ZSTD.mcapName())) {
            records = new byte[(int) uncompressedSize];
            from = 0;
            long n = Zstd.decompressByteArray(records, 0, records.length, r.data, r.at, (int) recordsLength);
            if (Zstd.isError(n) || n != uncompressedSize) {
                throw error(chunkStart, "zstd chunk does not decompress to its " + uncompressedSize + " bytes"
                        + (Zstd.isError(n) ? ": " + Zstd.getErrorName(n) : " (got " + n + ")"));
            }
        } else {
            throw error(chunkStart, "unsupported chunk compression '" + compression + "' (supported: none, zstd)");
        }
        if (crc != 0) {
            CRC32 actual = new CRC32();
            actual.update(records, from, (int) uncompressedSize);
            if (actual.getValue() != crc) {
                throw error(chunkStart, String.format("chunk CRC %08x differs from the recorded %08x",
                        actual.getValue(), crc));
            }
        }
        Cursor c = new Cursor(records, from, from + (int) uncompressedSize);
        while (c.at < c.limit) {
            int opcode = c.u8();
            long length = c.u64();
            c.need(length);
            int end = c.at + (int) length;
            dispatch(opcode, new Cursor(records, c.at, end), visitor, channels);
            c.at = end;
        }
    }

    /**
     * Reads the summary section through the footer, checking its CRC.
     *
     * @return the summary
     * @throws IOException if the file has no summary or it is malformed
     */
    public McapSummary summary() throws IOException {
        int footerAt = bytes.length - Opcode.MAGIC.length - FOOTER_BYTES;
        Cursor f = new Cursor(bytes, footerAt, bytes.length - Opcode.MAGIC.length);
        if (f.u8() != Opcode.FOOTER || f.u64() != 20) {
            throw error(footerAt, "no footer record before the trailing magic");
        }
        long summaryStart = f.u64();
        f.u64();
        int crcAt = f.at;
        long crc = f.u32();
        if (summaryStart == 0) {
            throw error(footerAt, "file has no summary section");
        }
        if (summaryStart < Opcode.MAGIC.length || summaryStart > footerAt) {
            throw error(footerAt, "summary start " + summaryStart + " outside the file");
        }
        if (crc != 0) {
            CRC32 actual = new CRC32();
            actual.update(bytes, (int) summaryStart, crcAt - (int) summaryStart);
            if (actual.getValue() != crc) {
                throw error(summaryStart, String.format("summary CRC %08x differs from the recorded %08x",
                        actual.getValue(), crc));
            }
        }
        Cursor h = new Cursor(bytes, Opcode.MAGIC.length, bytes.length);
        String profile = "";
        if (h.u8() == Opcode.HEADER) {
            h.u64();
            profile = h.string();
        }
        List<McapSchema> schemas = new ArrayList<>();
        List<McapChannel> channels = new ArrayList<>();
        McapStatistics statistics = null;
        int chunkIndexes = 0;
        Cursor c = new Cursor(bytes, (int) summaryStart, footerAt);
        while (c.at < c.limit) {
            int opcode = c.u8();
            long length = c.u64();
            c.need(length);
            int end = c.at + (int) length;
            Cursor r = new Cursor(bytes, c.at, end);
            switch (opcode) {
                case Opcode.SCHEMA -> schemas.add(schema(r));
                case Opcode.CHANNEL -> channels.add(channel(r));
                case Opcode.CHUNK_INDEX -> chunkIndexes++;
                case Opcode.STATISTICS -> statistics = statistics(r);
                default -> {
                    // summary offsets, metadata indexes
                }
            }
            c.at = end;
        }
        if (statistics == null) {
            throw error(summaryStart, "summary has no statistics record");
        }
        return new McapSummary(profile, List.copyOf(schemas), List.copyOf(channels), statistics, chunkIndexes);
    }

    private McapStatistics statistics(Cursor r) throws McapFormatException {
        long messages = r.u64();
        int schemas = r.u16();
        long channels = r.u32();
        r.u32();
        long metadata = r.u32();
        long chunks = r.u32();
        long start = r.u64();
        long end = r.u64();
        long n = r.u32();
        r.need(n);
        Map<Integer, Long> counts = new LinkedHashMap<>();
        int stop = r.at + (int) n;
        while (r.at < stop) {
            counts.put(r.u16(), r.u64());
        }
        return new McapStatistics(messages, schemas, channels, metadata, chunks, start, end, counts);
    }
}
