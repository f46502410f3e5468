package io.rtaware.record.mcap;

import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;
import java.util.zip.CRC32;

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
 *
 * <p>Split as foxglove/mcap's own readers are: this class opens the file and lexes the data
 * section record by record ({@code Pass}); {@link RecordCursor} parses one record's fields;
 * {@link DataSectionCrc} checks the data section's CRC; {@link ChunkDecompressor} turns a chunk's
 * stored bytes into its records; {@link SummaryReader} reads the summary section and the header.
 * Checked against foxglove/mcap's conformance suite ({@code McapConformanceTest}).
 */
public final class McapReader {

    /** The largest record or decompressed chunk, in MiB, that the reader allocates memory for. */
    public static final int MAX_RECORD_MIB = 256;
    private static final long MAX_RECORD_BYTES = McapBytes.MAX_RECORD_BYTES;
    private static final int RECORD_HEAD = McapBytes.RECORD_HEAD;
    /** A chunk's fields before its compression name: start, end, uncompressed size, CRC, name length. */
    private static final int CHUNK_FIXED = 8 + 8 + 8 + 4 + 4;
    private static final int MAX_COMPRESSION_NAME = 64;

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
            if (size < m || !McapBytes.readFully(ch, 0, head, 0, m) || !Arrays.equals(head, Opcode.MAGIC)) {
                throw new McapFormatException(path + ": not an MCAP file (no leading magic) at byte 0");
            }
            boolean finished = false;
            if (size >= 2L * m + McapBytes.FOOTER_BYTES) {
                byte[] tail = new byte[m];
                finished = McapBytes.readFully(ch, size - m, tail, 0, m) && Arrays.equals(tail, Opcode.MAGIC);
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
        return McapBytes.error(path, at, what);
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
                DataSectionCrc.check(path, ch, size);
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

    /** One sequential pass over the data section. */
    private final class Pass {
        private final FileChannel ch;
        private final McapVisitor visitor;
        private final Map<Integer, McapChannel> channels = new HashMap<>();
        private final CRC32 crc = new CRC32();
        private final byte[] head = new byte[RECORD_HEAD];
        private byte[] body = new byte[4096];
        private byte[] stored = new byte[0];
        private final ChunkDecompressor decompressor = new ChunkDecompressor(path);
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
            if (n > size - position || !McapBytes.readFully(ch, position, into, offset, n)) {
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
                long length = McapBytes.u64(head, 1);
                long left = size - position;
                if (length < 0 || length > left) {
                    throw error(recordAt, "record of " + Long.toUnsignedString(length) + " bytes overruns the file ("
                            + left + " bytes left)");
                }
                if (opcode == Opcode.DATA_END) {
                    byte[] b = body(length, recordAt);
                    take(b, 0, (int) length, recordAt);
                    long recorded = length >= 4 ? McapBytes.u32(b, 0) : 0;
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
                    dispatch(opcode, new RecordCursor(path, b, 0, (int) length, "the record at byte " + recordAt));
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
            long startNs = McapBytes.u64(fixed, 0);
            long endNs = McapBytes.u64(fixed, 8);
            long uncompressed = McapBytes.u64(fixed, 16);
            long recordedCrc = McapBytes.u32(fixed, 24);
            long nameLength = McapBytes.u32(fixed, 28);
            if (nameLength > MAX_COMPRESSION_NAME || nameLength > length - CHUNK_FIXED - 8) {
                throw error(chunkAt, "chunk compression name of " + nameLength + " bytes overruns its record");
            }
            byte[] rest = new byte[(int) nameLength + 8];
            take(rest, 0, rest.length, chunkAt);
            String compression = new String(rest, 0, (int) nameLength, StandardCharsets.UTF_8);
            long storedLength = McapBytes.u64(rest, (int) nameLength);
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
            if (!ChunkDecompressor.supports(compression)) {
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
            byte[] data = decompressor.records(compression, stored, (int) storedLength, (int) uncompressed, recordedCrc,
                    chunkAt);
            visitor.chunk(chunkAt, startNs, endNs);
            RecordCursor c = new RecordCursor(path, data, 0, (int) uncompressed, "the chunk at byte " + chunkAt);
            while (c.at < c.limit) {
                int opcode = c.u8();
                long recordLength = c.u64();
                c.need(recordLength);
                int end = c.at + (int) recordLength;
                dispatch(opcode, c.inner(end));
                c.at = end;
            }
        }

        private void skip(long n, long recordAt) throws IOException {
            byte[] b = body(Math.min(n, 1 << 16), recordAt);
            for (long left = n; left > 0; ) {
                int k = (int) Math.min(left, b.length);
                take(b, 0, k, recordAt);
                left -= k;
            }
        }

        private void dispatch(int opcode, RecordCursor r) throws McapFormatException {
            switch (opcode) {
                case Opcode.SCHEMA -> visitor.schema(r.schema());
                case Opcode.CHANNEL -> {
                    McapChannel channel = r.channel();
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

    /**
     * Reads the summary section through the footer, checking its CRC. A file without a summary
     * section (valid MCAP), or whose summary has no statistics record, is summarized by scanning
     * its data section.
     *
     * @return the summary
     * @throws IOException if the file is malformed or a CRC differs
     */
    public McapSummary summary() throws IOException {
        return new SummaryReader(this).summary();
    }

    /**
     * @return the header record's profile, read from the start of the file
     * @throws IOException if the file has no readable header record
     */
    public String profile() throws IOException {
        return new SummaryReader(this).profile();
    }
}
