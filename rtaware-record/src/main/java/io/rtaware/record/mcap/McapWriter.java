package io.rtaware.record.mcap;

import com.github.luben.zstd.Zstd;
import java.io.ByteArrayOutputStream;
import java.io.Closeable;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.channels.WritableByteChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.zip.CRC32;
import org.apache.commons.compress.compressors.lz4.FramedLZ4CompressorOutputStream;

/**
 * Writes an MCAP file (spec version 0, https://mcap.dev/spec): magic, header, schema and
 * channel records in the data section as they are added, messages in chunks (each followed by
 * its message index records), a data-end record with the data section's CRC32, and a summary
 * section (schemas, channels, chunk indexes, metadata indexes, statistics) with summary offset
 * records, the footer with the summary CRC32, and the closing magic.
 *
 * <p>Messages are appended to the open chunk in memory; a chunk is compressed and written once
 * it has reached the chunk size and a message with another log time comes, and at
 * {@link #close()}: messages of one log time stay in one chunk, so that chunks written in log-time
 * order do not share an instant (readers of a time range, and {@code mcap info}'s overlap count,
 * see chunks that do not overlap). A chunk holding {@value #SHARED_TIME_CHUNK_FACTOR} times the
 * chunk size of one log time is written all the same. Once the chunk buffers have grown to their
 * working size, {@link #writeMessage} allocates nothing; flushing a chunk allocates its index
 * entry (and, with lz4, its compressed frame). Not thread-safe: one writer thread.
 */
public final class McapWriter implements Closeable {

    /** Default uncompressed chunk size in bytes. */
    public static final int DEFAULT_CHUNK_BYTES = 1 << 20;

    /** A full chunk grows past its size for messages of its last log time up to this many chunk sizes. */
    public static final int SHARED_TIME_CHUNK_FACTOR = 4;

    private static final String LIBRARY = "rtaware";

    private final WritableByteChannel file;
    private final Compression compression;
    private final int chunkBytes;
    private final CRC32 dataCrc = new CRC32();
    private final CRC32 chunkCrc = new CRC32();
    private final ByteSink record = new ByteSink(4096);
    private final ByteSink chunk;
    private byte[] compressed = new byte[0];
    private long position;
    private boolean closed;

    private final ByteSink schemaRecords = new ByteSink(4096);
    private final ByteSink channelRecords = new ByteSink(4096);
    private final List<ChunkIndex> chunkIndexes = new ArrayList<>();
    private final ByteSink metadataIndexes = new ByteSink(256);
    private int schemaCount;
    private int channelCount;
    private int metadataCount;

    /** Per channel id: message count over the file, this chunk's index (log time, offset pairs). */
    private long[] channelMessages = new long[16];
    private int[] channelSequence = new int[16];
    private long[][] indexPairs = new long[16][];
    private int[] indexCount = new int[16];

    private long messageCount;
    private long messagesInChunk;
    private long durableMessages;
    private long messageStartNs = Long.MAX_VALUE;
    private long messageEndNs = Long.MIN_VALUE;
    private long chunkStartNs = Long.MAX_VALUE;
    private long chunkEndNs = Long.MIN_VALUE;

    private record ChunkIndex(long startNs, long endNs, long chunkOffset, long chunkLength,
                              Map<Integer, Long> messageIndexOffsets, long messageIndexLength,
                              long compressedSize, long uncompressedSize) {
    }

    /**
     * Creates (or truncates) the file and writes the magic and the header record.
     *
     * @param path the file
     * @param compression chunk compression
     * @param chunkBytes uncompressed chunk size at which a chunk is written, at least 1024
     * @param profile the header's profile (empty for none, {@code ros2} if every channel is ROS 2)
     * @throws IOException if the file cannot be created or written
     */
    public McapWriter(Path path, Compression compression, int chunkBytes, String profile) throws IOException {
        this(FileChannel.open(path, StandardOpenOption.CREATE, StandardOpenOption.WRITE,
                StandardOpenOption.TRUNCATE_EXISTING), compression, chunkBytes, profile);
    }

    /**
     * Writes to a channel of the caller's (closed by {@link #close()}; forced to disk if it is a
     * {@link FileChannel}), e.g. a test's channel that fails as a full disk does.
     *
     * @param channel where the bytes go
     * @param compression chunk compression
     * @param chunkBytes uncompressed chunk size at which a chunk is written, at least 1024
     * @param profile the header's profile (empty for none, {@code ros2} if every channel is ROS 2)
     * @throws IOException if the magic and header cannot be written
     */
    public McapWriter(WritableByteChannel channel, Compression compression, int chunkBytes, String profile)
            throws IOException {
        if (chunkBytes < 1024) {
            channel.close();
            throw new IllegalArgumentException("MCAP chunk size " + chunkBytes + " below 1024 bytes");
        }
        this.compression = compression;
        this.chunkBytes = chunkBytes;
        this.chunk = new ByteSink(chunkBytes + chunkBytes / 4);
        this.file = channel;
        record.bytes(Opcode.MAGIC, 0, Opcode.MAGIC.length);
        int c = record.beginRecord(Opcode.HEADER);
        record.string(profile);
        record.string(LIBRARY);
        record.endRecord(c);
        try {
            emitData(record);
        } catch (IOException e) {
            channel.close();
            throw e;
        }
    }

    /**
     * Adds a schema and writes its record.
     *
     * @param name e.g. {@code sensor_msgs/msg/LaserScan}
     * @param encoding e.g. {@code ros2msg}, {@code jsonschema}
     * @param data the schema text
     * @return the schema id (from 1)
     * @throws IOException if writing fails
     */
    public int addSchema(String name, String encoding, String data) throws IOException {
        int id = ++schemaCount;
        byte[] bytes = data.getBytes(StandardCharsets.UTF_8);
        record.clear();
        schemaRecord(record, id, name, encoding, bytes);
        schemaRecord(schemaRecords, id, name, encoding, bytes);
        emitData(record);
        return id;
    }

    /**
     * Adds a channel and writes its record.
     *
     * @param schemaId a schema id from {@link #addSchema}, or 0 for none
     * @param topic e.g. {@code /scan}
     * @param messageEncoding e.g. {@code cdr}, {@code json}
     * @param metadata free key/value pairs
     * @return the channel id (from 1)
     * @throws IOException if writing fails
     */
    public int addChannel(int schemaId, String topic, String messageEncoding, Map<String, String> metadata)
            throws IOException {
        if (schemaId < 0 || schemaId > schemaCount) {
            throw new IllegalArgumentException("unknown MCAP schema id " + schemaId);
        }
        int id = ++channelCount;
        if (id >= channelMessages.length) {
            int n = channelMessages.length * 2;
            channelMessages = Arrays.copyOf(channelMessages, n);
            channelSequence = Arrays.copyOf(channelSequence, n);
            indexPairs = Arrays.copyOf(indexPairs, n);
            indexCount = Arrays.copyOf(indexCount, n);
        }
        indexPairs[id] = new long[256];
        Map<String, String> sorted = new TreeMap<>(metadata);
        record.clear();
        channelRecord(record, id, schemaId, topic, messageEncoding, sorted);
        channelRecord(channelRecords, id, schemaId, topic, messageEncoding, sorted);
        emitData(record);
        return id;
    }

    private static void schemaRecord(ByteSink sink, int id, String name, String encoding, byte[] data) {
        int c = sink.beginRecord(Opcode.SCHEMA);
        sink.u16(id);
        sink.string(name);
        sink.string(encoding);
        sink.u32(data.length);
        sink.bytes(data, 0, data.length);
        sink.endRecord(c);
    }

    private static void channelRecord(ByteSink sink, int id, int schemaId, String topic, String messageEncoding,
                                      Map<String, String> metadata) {
        int c = sink.beginRecord(Opcode.CHANNEL);
        sink.u16(id);
        sink.u16(schemaId);
        sink.string(topic);
        sink.string(messageEncoding);
        sink.stringMap(metadata);
        sink.endRecord(c);
    }

    /**
     * Writes a metadata record (and indexes it in the summary).
     *
     * @param name the record's name
     * @param entries its key/value pairs
     * @throws IOException if writing fails
     */
    public void addMetadata(String name, Map<String, String> entries) throws IOException {
        flushChunk();
        record.clear();
        long offset = position;
        int c = record.beginRecord(Opcode.METADATA);
        record.string(name);
        record.stringMap(new LinkedHashMap<>(entries));
        record.endRecord(c);
        long length = record.size();
        emitData(record);
        int m = metadataIndexes.beginRecord(Opcode.METADATA_INDEX);
        metadataIndexes.u64(offset);
        metadataIndexes.u64(length);
        metadataIndexes.string(name);
        metadataIndexes.endRecord(m);
        metadataCount++;
    }

    /**
     * Appends a message to the open chunk, first writing the chunk if it is full and the message
     * does not share its last log time (see the class comment).
     *
     * @param channelId a channel id from {@link #addChannel}
     * @param logTimeNs log time in ns
     * @param publishTimeNs publish time in ns
     * @param data message bytes
     * @param offset first byte
     * @param length number of bytes
     * @throws IOException if a chunk had to be written and writing failed
     */
    public void writeMessage(int channelId, long logTimeNs, long publishTimeNs, byte[] data, int offset, int length)
            throws IOException {
        if (channelId < 1 || channelId > channelCount) {
            throw new IllegalArgumentException("unknown MCAP channel id " + channelId);
        }
        writeMessage(channelId, channelSequence[channelId]++, logTimeNs, publishTimeNs, data, offset, length);
    }

    /**
     * Appends a message with a sequence number of the caller's (MCAP: "an optional message
     * counter assigned by the publisher"; rtaware puts the commit's generation there, so that a
     * reader sees which generations a recording lacks).
     *
     * @param channelId a channel id from {@link #addChannel}
     * @param sequence the sequence number (its low 32 bits are written)
     * @param logTimeNs log time in ns
     * @param publishTimeNs publish time in ns
     * @param data message bytes
     * @param offset first byte
     * @param length number of bytes
     * @throws IOException if a chunk had to be written and writing failed
     */
    public void writeMessage(int channelId, long sequence, long logTimeNs, long publishTimeNs, byte[] data, int offset,
                             int length) throws IOException {
        if (channelId < 1 || channelId > channelCount) {
            throw new IllegalArgumentException("unknown MCAP channel id " + channelId);
        }
        if (chunk.size() >= chunkBytes
                && (logTimeNs != chunkEndNs || chunk.size() >= (long) SHARED_TIME_CHUNK_FACTOR * chunkBytes)) {
            flushChunk();
        }
        int recordOffset = chunk.size();
        chunk.u8(Opcode.MESSAGE);
        chunk.u64(2 + 4 + 8 + 8 + (long) length);
        chunk.u16(channelId);
        chunk.u32(sequence);
        chunk.u64(logTimeNs);
        chunk.u64(publishTimeNs);
        chunk.bytes(data, offset, length);

        long[] pairs = indexPairs[channelId];
        int n = indexCount[channelId];
        if (2 * n + 2 > pairs.length) {
            pairs = Arrays.copyOf(pairs, pairs.length * 2);
            indexPairs[channelId] = pairs;
        }
        pairs[2 * n] = logTimeNs;
        pairs[2 * n + 1] = recordOffset;
        indexCount[channelId] = n + 1;
        channelMessages[channelId]++;
        messageCount++;
        messagesInChunk++;
        chunkStartNs = Math.min(chunkStartNs, logTimeNs);
        chunkEndNs = Math.max(chunkEndNs, logTimeNs);
        messageStartNs = Math.min(messageStartNs, logTimeNs);
        messageEndNs = Math.max(messageEndNs, logTimeNs);
    }

    /** @return messages handed to the writer so far (some may still be in the open chunk) */
    public long messageCount() {
        return messageCount;
    }

    /** @return the earliest log time written so far (meaningless before the first message) */
    public long messageStartNs() {
        return messageStartNs;
    }

    /** @return the latest log time written so far (meaningless before the first message) */
    public long messageEndNs() {
        return messageEndNs;
    }

    /**
     * @param channelId a channel id from {@link #addChannel}
     * @return messages written on it so far
     */
    public long channelMessageCount(int channelId) {
        return channelMessages[channelId];
    }

    /**
     * @return messages in chunks written whole to the file: what a reader (or
     *     {@code inspect --recover}) finds there if the file is never finished
     */
    public long durableMessageCount() {
        return durableMessages;
    }

    /** @return bytes in the file so far (chunk in memory not included) */
    public long fileBytes() {
        return position;
    }

    /**
     * Writes the open chunk, if it holds any message, and its message indexes.
     *
     * @throws IOException if writing fails
     */
    public void flushChunk() throws IOException {
        if (chunk.size() == 0) {
            return;
        }
        int uncompressed = chunk.size();
        chunkCrc.reset();
        chunkCrc.update(chunk.array(), 0, uncompressed);
        byte[] payload;
        int payloadLength;
        if (compression == Compression.ZSTD) {
            int bound = (int) Zstd.compressBound(uncompressed);
            if (compressed.length < bound) {
                compressed = new byte[bound];
            }
            long n = Zstd.compressByteArray(compressed, 0, compressed.length, chunk.array(), 0, uncompressed, 3);
            if (Zstd.isError(n)) {
                throw new IOException("zstd compression failed: " + Zstd.getErrorName(n));
            }
            payload = compressed;
            payloadLength = (int) n;
        } else if (compression == Compression.LZ4) {
            ByteArrayOutputStream frame = new ByteArrayOutputStream(uncompressed / 2 + 64);
            try (FramedLZ4CompressorOutputStream lz4 = new FramedLZ4CompressorOutputStream(frame)) {
                lz4.write(chunk.array(), 0, uncompressed);
            }
            payload = frame.toByteArray();
            payloadLength = payload.length;
        } else {
            payload = chunk.array();
            payloadLength = uncompressed;
        }
        long chunkOffset = position;
        record.clear();
        int c = record.beginRecord(Opcode.CHUNK);
        record.u64(chunkStartNs);
        record.u64(chunkEndNs);
        record.u64(uncompressed);
        record.u32(chunkCrc.getValue());
        record.string(compression.mcapName());
        record.u64(payloadLength);
        int headerBytes = record.size();
        record.u64At(c - 8, headerBytes - c + payloadLength);
        emitData(record);
        emitData(payload, 0, payloadLength);
        long chunkLength = position - chunkOffset;

        Map<Integer, Long> indexOffsets = new TreeMap<>();
        long indexStart = position;
        for (int id = 1; id <= channelCount; id++) {
            int n = indexCount[id];
            if (n == 0) {
                continue;
            }
            indexOffsets.put(id, position);
            record.clear();
            int m = record.beginRecord(Opcode.MESSAGE_INDEX);
            record.u16(id);
            record.u32(16L * n);
            long[] pairs = indexPairs[id];
            for (int i = 0; i < 2 * n; i++) {
                record.u64(pairs[i]);
            }
            record.endRecord(m);
            emitData(record);
            indexCount[id] = 0;
        }
        chunkIndexes.add(new ChunkIndex(chunkStartNs, chunkEndNs, chunkOffset, chunkLength, indexOffsets,
                position - indexStart, payloadLength, uncompressed));
        chunk.clear();
        durableMessages += messagesInChunk;
        messagesInChunk = 0;
        chunkStartNs = Long.MAX_VALUE;
        chunkEndNs = Long.MIN_VALUE;
    }

    private void emitData(ByteSink sink) throws IOException {
        emitData(sink.array(), 0, sink.size());
        sink.clear();
    }

    private void emitData(byte[] bytes, int offset, int length) throws IOException {
        dataCrc.update(bytes, offset, length);
        write(bytes, offset, length);
    }

    private void write(byte[] bytes, int offset, int length) throws IOException {
        ByteBuffer buffer = ByteBuffer.wrap(bytes, offset, length);
        while (buffer.hasRemaining()) {
            position += file.write(buffer);
        }
    }

    /**
     * Writes the last chunk, the data end, the summary and the footer, and closes the file. Safe
     * to call more than once.
     *
     * @throws IOException if writing fails
     */
    @Override
    public void close() throws IOException {
        if (closed) {
            return;
        }
        closed = true;
        try {
            flushChunk();
            record.clear();
            int d = record.beginRecord(Opcode.DATA_END);
            record.u32(dataCrc.getValue());
            record.endRecord(d);
            write(record.array(), 0, record.size());
            record.clear();

            long summaryStart = position;
            ByteSink summary = new ByteSink(8192);
            List<long[]> groups = new ArrayList<>();
            group(summary, groups, Opcode.SCHEMA, schemaRecords);
            group(summary, groups, Opcode.CHANNEL, channelRecords);
            ByteSink indexes = new ByteSink(256 + chunkIndexes.size() * 96);
            for (ChunkIndex ci : chunkIndexes) {
                int c = indexes.beginRecord(Opcode.CHUNK_INDEX);
                indexes.u64(ci.startNs());
                indexes.u64(ci.endNs());
                indexes.u64(ci.chunkOffset());
                indexes.u64(ci.chunkLength());
                indexes.u32(10L * ci.messageIndexOffsets().size());
                for (Map.Entry<Integer, Long> e : ci.messageIndexOffsets().entrySet()) {
                    indexes.u16(e.getKey());
                    indexes.u64(e.getValue());
                }
                indexes.u64(ci.messageIndexLength());
                indexes.string(compression.mcapName());
                indexes.u64(ci.compressedSize());
                indexes.u64(ci.uncompressedSize());
                indexes.endRecord(c);
            }
            group(summary, groups, Opcode.CHUNK_INDEX, indexes);
            group(summary, groups, Opcode.METADATA_INDEX, metadataIndexes);
            ByteSink stats = new ByteSink(256);
            int s = stats.beginRecord(Opcode.STATISTICS);
            stats.u64(messageCount);
            stats.u16(schemaCount);
            stats.u32(channelCount);
            stats.u32(0);
            stats.u32(metadataCount);
            stats.u32(chunkIndexes.size());
            stats.u64(messageCount == 0 ? 0 : messageStartNs);
            stats.u64(messageCount == 0 ? 0 : messageEndNs);
            stats.u32(10L * channelCount);
            for (int id = 1; id <= channelCount; id++) {
                stats.u16(id);
                stats.u64(channelMessages[id]);
            }
            stats.endRecord(s);
            group(summary, groups, Opcode.STATISTICS, stats);

            long summaryOffsetStart = summaryStart + summary.size();
            for (long[] g : groups) {
                int o = summary.beginRecord(Opcode.SUMMARY_OFFSET);
                summary.u8((int) g[0]);
                summary.u64(summaryStart + g[1]);
                summary.u64(g[2]);
                summary.endRecord(o);
            }
            summary.u8(Opcode.FOOTER);
            summary.u64(8 + 8 + 4);
            summary.u64(summaryStart);
            summary.u64(summaryOffsetStart);
            CRC32 summaryCrc = new CRC32();
            summaryCrc.update(summary.array(), 0, summary.size());
            summary.u32(summaryCrc.getValue());
            summary.bytes(Opcode.MAGIC, 0, Opcode.MAGIC.length);
            write(summary.array(), 0, summary.size());
            if (file instanceof FileChannel fileChannel) {
                fileChannel.force(false);
            }
        } finally {
            file.close();
        }
    }

    private static void group(ByteSink summary, List<long[]> groups, int opcode, ByteSink records) {
        if (records.size() == 0) {
            return;
        }
        groups.add(new long[] {opcode, summary.size(), records.size()});
        summary.bytes(records.array(), 0, records.size());
    }
}
