package io.rtaware.record.mcap;

import com.github.luben.zstd.Zstd;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.zip.CRC32;
import org.apache.commons.compress.compressors.lz4.FramedLZ4CompressorInputStream;

/**
 * Reads MCAP files (spec version 0, https://mcap.dev/spec) as a stream, one record and one chunk
 * at a time, so memory stays bounded by the largest chunk whatever the file's size.
 *
 * <p>What it refuses, each with a {@link McapFormatException} whose message is one line naming the
 * file, the problem and the byte: a path that is not a regular file (a FIFO, a device such as
 * {@code /dev/zero}, a folder: refused before it is opened, so nothing blocks); a file whose first
 * eight bytes are not the magic (checked before anything else is read); any length that overruns
 * the file or its record (checked before anything is allocated for it); a record or chunk larger
 * than {@value #MAX_RECORD_MIB} MiB; a data section whose CRC differs (checked over the whole
 * section before any chunk is decompressed, when the file is finished); a chunk that does not
 * decompress to its declared size or whose CRC differs. Chunks may be uncompressed, zstd or lz4.
 * Files without a summary section are read by scanning their data section.
 */
public final class McapReader {

    /** The largest record or decompressed chunk, in MiB, that the reader allocates memory for. */
    public static final int MAX_RECORD_MIB = 256;
    private static final long MAX_RECORD_BYTES = (long) MAX_RECORD_MIB << 20;
    private static final VarHandle I16 = MethodHandles.byteArrayViewVarHandle(short[].class, ByteOrder.LITTLE_ENDIAN);
    private static final VarHandle I32 = MethodHandles.byteArrayViewVarHandle(int[].class, ByteOrder.LITTLE_ENDIAN);
    private static final VarHandle I64 = MethodHandles.byteArrayViewVarHandle(long[].class, ByteOrder.LITTLE_ENDIAN);
    /** Footer record: opcode, length, summary start, summary offset start, CRC. */
    static final int FOOTER_BYTES = 1 + 8 + 8 + 8 + 4;
    /** Data-end record: opcode, length, CRC. */
    private static final int DATA_END_BYTES = 1 + 8 + 4;
    /** Opcode and length that start every record. */
    private static final int RECORD_HEAD = 1 + 8;
    /** A chunk's fields before its compression name: start, end, uncompressed size, CRC, name length. */
    private static final int CHUNK_FIXED = 8 + 8 + 8 + 4 + 4;
    private static final int MAX_COMPRESSION_NAME = 64;
    private static final int CRC_BLOCK = 1 << 20;

    private final Path path;
    private final long size;
    private final boolean finished;

    private McapReader(Path path, long size, boolean finished) {
        this.path = path;
        this.size = size;
        this.finished = finished;
    }

    /**
     * Opens a finished file: a regular file with the leading magic (checked first) and the
     * trailing magic.
     *
     * @param path the file
     * @return a reader
     * @throws IOException if it cannot be read, is not a regular file, is not MCAP, or is unfinished
     */
    public static McapReader open(Path path) throws IOException {
        McapReader reader = openUnfinished(path);
        if (!reader.finished) {
            throw reader.error(reader.size, "MCAP file not finished (no footer and trailing magic): the run that"
                    + " wrote it was killed or its disk was full; 'rtaware inspect --recover' writes what it holds");
        }
        return reader;
    }

    /**
     * Opens a file that may be unfinished (a recording whose writer was killed): only the leading
     * magic is required. {@link #read} then reads up to the first record the file cuts off.
     *
     * @param path the file
     * @return a reader
     * @throws IOException if it cannot be read, is not a regular file or is not MCAP
     */
    public static McapReader openUnfinished(Path path) throws IOException {
        BasicFileAttributes attributes = Files.readAttributes(path, BasicFileAttributes.class);
        if (!attributes.isRegularFile()) {
            String kind = attributes.isDirectory() ? "a folder" : "a FIFO, socket or device";
            throw new McapFormatException(path + ": not a regular file (" + kind + "); an MCAP recording is a file");
        }
        try (FileChannel ch = FileChannel.open(path, StandardOpenOption.READ)) {
            long size = ch.size();
            int m = Opcode.MAGIC.length;
            byte[] head = new byte[m];
            if (size < m || !readFully(ch, 0, head, 0, m) || !Arrays.equals(head, Opcode.MAGIC)) {
                throw new McapFormatException(path + ": not an MCAP file (no leading magic) at byte 0");
            }
            boolean finished = false;
            if (size >= 2L * m + FOOTER_BYTES) {
                byte[] tail = new byte[m];
                finished = readFully(ch, size - m, tail, 0, m) && Arrays.equals(tail, Opcode.MAGIC);
            }
            return new McapReader(path, size, finished);
        }
    }

    /** @return the file's size in bytes when it was opened */
    public long sizeBytes() {
        return size;
    }

    /** @return true if the file ends with a footer and the trailing magic */
    public boolean finished() {
        return finished;
    }

    /** @return the file */
    public Path path() {
        return path;
    }

    private McapFormatException error(long at, String what) {
        return new McapFormatException(path + ": " + what + " at byte " + at);
    }

    /** Reads exactly {@code n} bytes at {@code position}; false if the file ends first. */
    private static boolean readFully(FileChannel ch, long position, byte[] into, int offset, int n) throws IOException {
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

    private static long u64(byte[] b, int at) {
        return (long) I64.get(b, at);
    }

    private static long u32(byte[] b, int at) {
        return (int) I32.get(b, at) & 0xffffffffL;
    }

    /** A bounded cursor over a record's bytes; errors name the record's place in the file. */
    private final class Cursor {
        final byte[] data;
        int at;
        final int limit;
        final String where;

        Cursor(byte[] data, int from, int limit, String where) {
            this.data = data;
            this.at = from;
            this.limit = limit;
            this.where = where;
        }

        void need(long n) throws McapFormatException {
            if (n < 0 || n > limit - at) {
                throw new McapFormatException(path + ": record field of " + n + " bytes overruns its record ("
                        + (limit - at) + " left) in " + where);
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
            Cursor inner = new Cursor(data, at, end, where);
            while (inner.at < end) {
                map.put(inner.string(), inner.string());
            }
            at = end;
            return map;
        }
    }

    /**
     * Hands every schema, channel, metadata and message record of the data section to the
     * visitor, in file order, one chunk in memory at a time. A finished file's data-section CRC is
     * checked before any chunk is decompressed; each chunk's CRC after it is decompressed.
     *
     * @param visitor receives the records
     * @throws IOException if the file is malformed, a CRC differs, or (an unfinished file) it ends
     *     inside a record: the visitor has then seen every record before that one
     */
    public void read(McapVisitor visitor) throws IOException {
        try (FileChannel ch = FileChannel.open(path, StandardOpenOption.READ)) {
            if (finished) {
                checkDataSectionCrc(ch);
            }
            new Pass(ch, visitor).run();
        }
    }

    /**
     * Where a read of a possibly damaged or unfinished file ended.
     *
     * @param goodBytes bytes from the start of the file up to the first record that could not be
     *     read (the file's size if every record was read)
     * @param problem why that record could not be read, or why the file is not whole though every
     *     record was read (it ends without its data end, summary and footer); null if it was whole
     */
    public record ReadEnd(long goodBytes, String problem) {
    }

    /**
     * Like {@link #read}, for recovering what an unfinished or damaged file holds: hands every
     * record to the visitor up to the first that cannot be read (a chunk is handed over only
     * once its CRC is checked), without checking the data section's CRC first, and says where it
     * stopped instead of throwing.
     *
     * @param visitor receives the records
     * @return where reading ended and why
     * @throws IOException if the file cannot be read at all
     */
    public ReadEnd readRecoverable(McapVisitor visitor) throws IOException {
        try (FileChannel ch = FileChannel.open(path, StandardOpenOption.READ)) {
            Pass pass = new Pass(ch, visitor);
            try {
                pass.run();
                return new ReadEnd(size, finished ? null : "the file ends after a complete record, without its data end, "
                        + "summary and footer (its writer did not finish it)");
            } catch (McapFormatException e) {
                return new ReadEnd(pass.recordAt, e.getMessage());
            }
        }
    }

    /**
     * Checks the data section's CRC, recorded in the data-end record just before the summary (or
     * the footer), over the bytes as stored, so a damaged compressed chunk is named before a
     * decompressor sees it. Skipped when the data-end record is not where a writer puts it or
     * records no CRC; the sequential pass then checks what it can.
     */
    private void checkDataSectionCrc(FileChannel ch) throws IOException {
        long footerAt = size - Opcode.MAGIC.length - FOOTER_BYTES;
        byte[] footer = new byte[FOOTER_BYTES];
        if (!readFully(ch, footerAt, footer, 0, FOOTER_BYTES) || footer[0] != Opcode.FOOTER) {
            return;
        }
        long summaryStart = u64(footer, RECORD_HEAD);
        long dataEndAt = (summaryStart == 0 ? footerAt : summaryStart) - DATA_END_BYTES;
        if (dataEndAt < Opcode.MAGIC.length || dataEndAt > footerAt) {
            return;
        }
        byte[] dataEnd = new byte[DATA_END_BYTES];
        if (!readFully(ch, dataEndAt, dataEnd, 0, DATA_END_BYTES) || dataEnd[0] != Opcode.DATA_END
                || u64(dataEnd, 1) != 4) {
            return;
        }
        long recorded = u32(dataEnd, RECORD_HEAD);
        if (recorded == 0) {
            return;
        }
        CRC32 crc = new CRC32();
        byte[] block = new byte[(int) Math.min(CRC_BLOCK, dataEndAt)];
        for (long at = 0; at < dataEndAt; ) {
            int n = (int) Math.min(block.length, dataEndAt - at);
            if (!readFully(ch, at, block, 0, n)) {
                throw error(at, "file shrank while being read");
            }
            crc.update(block, 0, n);
            at += n;
        }
        if (crc.getValue() != recorded) {
            throw error(dataEndAt, String.format("data section CRC %08x differs from the recorded %08x (the file"
                    + " is damaged)", crc.getValue(), recorded));
        }
    }

    /** One sequential pass over the data section. */
    private final class Pass {
        private final FileChannel ch;
        private final McapVisitor visitor;
        private final Map<Integer, McapChannel> channels = new HashMap<>();
        private final CRC32 crc = new CRC32();
        private final byte[] head = new byte[RECORD_HEAD];
        private byte[] body = new byte[4096];
        private byte[] stored = new byte[0];
        private byte[] records = new byte[0];
        private long position = Opcode.MAGIC.length;
        /** Where the record being read starts. */
        long recordAt = Opcode.MAGIC.length;

        Pass(FileChannel ch, McapVisitor visitor) {
            this.ch = ch;
            this.visitor = visitor;
            crc.update(Opcode.MAGIC, 0, Opcode.MAGIC.length);
        }

        /** Reads {@code n} bytes at the pass's position into {@code into}, adding them to the CRC. */
        private void take(byte[] into, int offset, int n, long recordAt) throws IOException {
            if (n > size - position || !readFully(ch, position, into, offset, n)) {
                throw error(recordAt, "file ends inside the record");
            }
            crc.update(into, offset, n);
            position += n;
        }

        void run() throws IOException {
            while (true) {
                recordAt = position;
                if (size - position < RECORD_HEAD) {
                    throw error(recordAt, size == position ? "MCAP data section has no data-end record"
                            : "file ends inside a record's opcode and length");
                }
                long crcBefore = crc.getValue();
                take(head, 0, RECORD_HEAD, recordAt);
                int opcode = head[0] & 0xff;
                long length = u64(head, 1);
                long left = size - position;
                if (length < 0 || length > left) {
                    throw error(recordAt, "record of " + Long.toUnsignedString(length) + " bytes overruns the file ("
                            + left + " bytes left)");
                }
                if (opcode == Opcode.DATA_END) {
                    byte[] b = body(length, recordAt);
                    take(b, 0, (int) length, recordAt);
                    long recorded = length >= 4 ? u32(b, 0) : 0;
                    if (recorded != 0 && recorded != crcBefore) {
                        throw error(recordAt, String.format("data section CRC %08x differs from the recorded %08x",
                                crcBefore, recorded));
                    }
                    return;
                }
                if (opcode == Opcode.CHUNK) {
                    chunk(recordAt, length);
                } else {
                    byte[] b = body(length, recordAt);
                    take(b, 0, (int) length, recordAt);
                    dispatch(opcode, new Cursor(b, 0, (int) length, "the record at byte " + recordAt));
                }
            }
        }

        private byte[] body(long length, long recordAt) throws McapFormatException {
            if (length > MAX_RECORD_BYTES) {
                throw error(recordAt, "record of " + length + " bytes is larger than the reader's limit of "
                        + MAX_RECORD_MIB + " MiB");
            }
            if (body.length < length) {
                body = new byte[(int) length];
            }
            return body;
        }

        private void chunk(long chunkAt, long length) throws IOException {
            if (length < CHUNK_FIXED + 8) {
                throw error(chunkAt, "chunk record of " + length + " bytes is too short for its fields");
            }
            byte[] fixed = new byte[CHUNK_FIXED];
            take(fixed, 0, CHUNK_FIXED, chunkAt);
            long startNs = u64(fixed, 0);
            long endNs = u64(fixed, 8);
            long uncompressed = u64(fixed, 16);
            long recordedCrc = u32(fixed, 24);
            long nameLength = u32(fixed, 28);
            if (nameLength > MAX_COMPRESSION_NAME || nameLength > length - CHUNK_FIXED - 8) {
                throw error(chunkAt, "chunk compression name of " + nameLength + " bytes overruns its record");
            }
            byte[] rest = new byte[(int) nameLength + 8];
            take(rest, 0, rest.length, chunkAt);
            String compression = new String(rest, 0, (int) nameLength, StandardCharsets.UTF_8);
            long storedLength = u64(rest, (int) nameLength);
            long available = length - CHUNK_FIXED - rest.length;
            if (storedLength < 0 || storedLength > available) {
                throw error(chunkAt, "chunk records of " + Long.toUnsignedString(storedLength)
                        + " bytes overrun the chunk (" + available + " bytes left)");
            }
            if (uncompressed < 0 || uncompressed > MAX_RECORD_BYTES) {
                throw error(chunkAt, "chunk declares " + Long.toUnsignedString(uncompressed)
                        + " bytes uncompressed, more than the reader's limit of " + MAX_RECORD_MIB + " MiB");
            }
            if (storedLength > MAX_RECORD_BYTES) {
                throw error(chunkAt, "chunk of " + storedLength + " bytes is larger than the reader's limit of "
                        + MAX_RECORD_MIB + " MiB");
            }
            if (compression.isEmpty() && uncompressed != storedLength) {
                throw error(chunkAt, "uncompressed chunk sizes differ: " + uncompressed + " vs " + storedLength);
            }
            if (!compression.isEmpty() && !compression.equals(Compression.ZSTD.mcapName())
                    && !compression.equals(Compression.LZ4.mcapName())) {
                throw error(chunkAt, "unsupported chunk compression '" + compression + "' (supported: none, zstd, lz4)");
            }
            if (stored.length < storedLength) {
                stored = new byte[(int) storedLength];
            }
            take(stored, 0, (int) storedLength, chunkAt);
            long padding = available - storedLength;
            if (padding > 0) {
                skip(padding, chunkAt);
            }
            byte[] data;
            if (compression.isEmpty()) {
                data = stored;
            } else {
                if (records.length < uncompressed) {
                    records = new byte[(int) uncompressed];
                }
                decompress(compression, (int) storedLength, (int) uncompressed, chunkAt);
                data = records;
            }
            if (recordedCrc != 0) {
                CRC32 actual = new CRC32();
                actual.update(data, 0, (int) uncompressed);
                if (actual.getValue() != recordedCrc) {
                    throw error(chunkAt, String.format("chunk CRC %08x differs from the recorded %08x",
                            actual.getValue(), recordedCrc));
                }
            }
            visitor.chunk(chunkAt, startNs, endNs);
            Cursor c = new Cursor(data, 0, (int) uncompressed, "the chunk at byte " + chunkAt);
            while (c.at < c.limit) {
                int opcode = c.u8();
                long recordLength = c.u64();
                c.need(recordLength);
                int end = c.at + (int) recordLength;
                dispatch(opcode, new Cursor(data, c.at, end, c.where));
                c.at = end;
            }
        }

        private void decompress(String compression, int storedLength, int uncompressed, long chunkAt)
                throws McapFormatException {
            String problem;
            try {
                if (compression.equals(Compression.ZSTD.mcapName())) {
                    long declared = Zstd.getFrameContentSize(stored, 0, storedLength);
                    if (declared >= 0 && declared != uncompressed) {
                        throw error(chunkAt, "zstd chunk's frame says " + declared + " bytes, its record "
                                + uncompressed);
                    }
                    long n = Zstd.decompressByteArray(records, 0, uncompressed, stored, 0, storedLength);
                    if (!Zstd.isError(n) && n == uncompressed) {
                        return;
                    }
                    problem = Zstd.isError(n) ? Zstd.getErrorName(n) : "got " + n + " bytes";
                } else {
                    try (InputStream in = new FramedLZ4CompressorInputStream(
                            new ByteArrayInputStream(stored, 0, storedLength))) {
                        int n = in.readNBytes(records, 0, uncompressed);
                        if (n == uncompressed && in.read() < 0) {
                            return;
                        }
                        problem = n < uncompressed ? "got " + n + " bytes" : "more bytes than declared";
                    }
                }
            } catch (McapFormatException e) {
                throw e;
            } catch (IOException | RuntimeException e) {
                // zstd-jni throws ZstdException on damaged frames; Commons Compress an IOException.
                problem = e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
            }
            throw error(chunkAt, compression + " chunk does not decompress to its " + uncompressed + " bytes: " + problem);
        }

        private void skip(long n, long recordAt) throws IOException {
            byte[] b = body(Math.min(n, 1 << 16), recordAt);
            for (long left = n; left > 0; ) {
                int k = (int) Math.min(left, b.length);
                take(b, 0, k, recordAt);
                left -= k;
            }
        }

        private void dispatch(int opcode, Cursor r) throws McapFormatException {
            switch (opcode) {
                case Opcode.SCHEMA -> visitor.schema(schema(r));
                case Opcode.CHANNEL -> {
                    McapChannel channel = channel(r);
                    channels.put(channel.id(), channel);
                    visitor.channel(channel);
                }
                case Opcode.METADATA -> visitor.metadata(r.string(), r.stringMap());
                case Opcode.MESSAGE -> {
                    int channelId = r.u16();
                    long sequence = r.u32();
                    long logTime = r.u64();
                    long publishTime = r.u64();
                    McapChannel channel = channels.get(channelId);
                    if (channel == null) {
                        throw new McapFormatException(path + ": message on channel " + channelId
                                + " before its channel record in " + r.where);
                    }
                    visitor.message(channel, sequence, logTime, publishTime, r.data, r.at, r.limit - r.at);
                }
                default -> {
                    // header, indexes, attachments: nothing for the visitor
                }
            }
        }
    }

    private static McapSchema schema(Cursor r) throws McapFormatException {
        int id = r.u16();
        String name = r.string();
        String encoding = r.string();
        long n = r.u32();
        r.need(n);
        String data = new String(r.data, r.at, (int) n, StandardCharsets.UTF_8);
        return new McapSchema(id, name, encoding, data);
    }

    private static McapChannel channel(Cursor r) throws McapFormatException {
        return new McapChannel(r.u16(), r.u16(), r.string(), r.string(), r.stringMap());
    }

    /**
     * Reads the summary section through the footer, checking its CRC. A file without a summary
     * section (valid MCAP), or whose summary has no statistics record, is summarized by scanning
     * its data section.
     *
     * @return the summary
     * @throws IOException if the file is malformed or a CRC differs
     */
    public McapSummary summary() throws IOException {
        if (!finished) {
            return scan(readProfile());
        }
        long footerAt = size - Opcode.MAGIC.length - FOOTER_BYTES;
        byte[] footer = new byte[FOOTER_BYTES];
        String profile = readProfile();
        try (FileChannel ch = FileChannel.open(path, StandardOpenOption.READ)) {
            if (!readFully(ch, footerAt, footer, 0, FOOTER_BYTES) || footer[0] != Opcode.FOOTER
                    || u64(footer, 1) != 20) {
                throw error(footerAt, "no footer record before the trailing magic");
            }
            long summaryStart = u64(footer, RECORD_HEAD);
            long recordedCrc = u32(footer, RECORD_HEAD + 16);
            if (summaryStart == 0) {
                return scan(profile);
            }
            if (summaryStart < Opcode.MAGIC.length || summaryStart > footerAt) {
                throw error(footerAt, "summary start " + Long.toUnsignedString(summaryStart) + " outside the file");
            }
            long summaryBytes = footerAt - summaryStart;
            if (summaryBytes > MAX_RECORD_BYTES) {
                throw error(summaryStart, "summary section of " + summaryBytes + " bytes is larger than the reader's"
                        + " limit of " + MAX_RECORD_MIB + " MiB");
            }
            byte[] bytes = new byte[(int) summaryBytes + FOOTER_BYTES - 4];
            if (!readFully(ch, summaryStart, bytes, 0, bytes.length)) {
                throw error(summaryStart, "file shrank while being read");
            }
            if (recordedCrc != 0) {
                CRC32 actual = new CRC32();
                actual.update(bytes, 0, bytes.length);
                if (actual.getValue() != recordedCrc) {
                    throw error(summaryStart, String.format("summary CRC %08x differs from the recorded %08x",
                            actual.getValue(), recordedCrc));
                }
            }
            return summary(profile, bytes, (int) summaryBytes, summaryStart);
        }
    }

    private McapSummary summary(String profile, byte[] bytes, int length, long summaryStart) throws IOException {
        List<McapSchema> schemas = new ArrayList<>();
        List<McapChannel> channels = new ArrayList<>();
        McapStatistics statistics = null;
        int chunkIndexes = 0;
        Cursor c = new Cursor(bytes, 0, length, "the summary at byte " + summaryStart);
        while (c.at < c.limit) {
            int opcode = c.u8();
            long recordLength = c.u64();
            c.need(recordLength);
            int end = c.at + (int) recordLength;
            Cursor r = new Cursor(bytes, c.at, end, c.where);
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
            return scan(profile);
        }
        return new McapSummary(profile, List.copyOf(schemas), List.copyOf(channels), statistics, chunkIndexes);
    }

    /**
     * @return the header record's profile, read from the start of the file
     * @throws IOException if the file has no readable header record
     */
    public String profile() throws IOException {
        return readProfile();
    }

    private String readProfile() throws IOException {
        try (FileChannel ch = FileChannel.open(path, StandardOpenOption.READ)) {
            byte[] head = new byte[RECORD_HEAD];
            long at = Opcode.MAGIC.length;
            if (!readFully(ch, at, head, 0, RECORD_HEAD) || head[0] != Opcode.HEADER) {
                throw error(at, "no header record after the magic");
            }
            long length = u64(head, 1);
            if (length < 0 || length > Math.min(MAX_RECORD_BYTES, size - at - RECORD_HEAD)) {
                throw error(at, "header record of " + Long.toUnsignedString(length) + " bytes overruns the file");
            }
            byte[] body = new byte[(int) length];
            if (!readFully(ch, at + RECORD_HEAD, body, 0, body.length)) {
                throw error(at, "file ends inside the header record");
            }
            return new Cursor(body, 0, body.length, "the header record").string();
        }
    }

    /** A summary made by reading the data section (a file without a summary section). */
    private McapSummary scan(String profile) throws IOException {
        List<McapSchema> schemas = new ArrayList<>();
        List<McapChannel> channels = new ArrayList<>();
        Map<Integer, Long> counts = new LinkedHashMap<>();
        long[] totals = {0, Long.MAX_VALUE, Long.MIN_VALUE, 0, 0};
        read(new McapVisitor() {
            @Override
            public void schema(McapSchema schema) {
                schemas.add(schema);
            }

            @Override
            public void channel(McapChannel channel) {
                channels.add(channel);
                counts.putIfAbsent(channel.id(), 0L);
            }

            @Override
            public void metadata(String name, Map<String, String> entries) {
                totals[3]++;
            }

            @Override
            public void chunk(long fileOffset, long startNs, long endNs) {
                totals[4]++;
            }

            @Override
            public void message(McapChannel channel, long sequence, long logTimeNs, long publishTimeNs,
                                byte[] data, int offset, int length) {
                totals[0]++;
                totals[1] = Math.min(totals[1], logTimeNs);
                totals[2] = Math.max(totals[2], logTimeNs);
                counts.merge(channel.id(), 1L, Long::sum);
            }
        });
        McapStatistics statistics = new McapStatistics(totals[0], schemas.size(), channels.size(), totals[3], totals[4],
                totals[0] == 0 ? 0 : totals[1], totals[0] == 0 ? 0 : totals[2], counts);
        return new McapSummary(profile, List.copyOf(schemas), List.copyOf(channels), statistics, 0);
    }

    private static McapStatistics statistics(Cursor r) throws McapFormatException {
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
