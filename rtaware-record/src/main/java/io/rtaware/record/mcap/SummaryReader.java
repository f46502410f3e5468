package io.rtaware.record.mcap;

import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.zip.CRC32;

/**
 * What a file says about itself: the header's profile, and the summary section through the
 * footer (its CRC checked), or, for a file without one (valid MCAP) or whose summary has no
 * statistics record, a summary made by reading its data section.
 */
final class SummaryReader {

    private final McapReader reader;

    /** @param reader the file's reader (its data section is read when there is no summary) */
    SummaryReader(McapReader reader) {
        this.reader = reader;
    }

    /**
     * @return the summary
     * @throws IOException if the file is malformed or a CRC differs
     */
    McapSummary summary() throws IOException {
        String profile = profile();
        if (!reader.finished()) {
            return scan(profile);
        }
        long size = reader.sizeBytes();
        long footerAt = size - Opcode.MAGIC.length - McapBytes.FOOTER_BYTES;
        byte[] footer = new byte[McapBytes.FOOTER_BYTES];
        try (FileChannel ch = FileChannel.open(reader.path(), StandardOpenOption.READ)) {
            if (!McapBytes.readFully(ch, footerAt, footer, 0, McapBytes.FOOTER_BYTES) || footer[0] != Opcode.FOOTER
                    || McapBytes.u64(footer, 1) != 20) {
                throw McapBytes.error(reader.path(), footerAt, "no footer record before the trailing magic");
            }
            long summaryStart = McapBytes.u64(footer, McapBytes.RECORD_HEAD);
            long recordedCrc = McapBytes.u32(footer, McapBytes.RECORD_HEAD + 16);
            if (summaryStart == 0) {
                return scan(profile);
            }
            if (summaryStart < Opcode.MAGIC.length || summaryStart > footerAt) {
                throw McapBytes.error(reader.path(), footerAt, "summary start " + Long.toUnsignedString(summaryStart)
                        + " outside the file");
            }
            long summaryBytes = footerAt - summaryStart;
            if (summaryBytes > McapBytes.MAX_RECORD_BYTES) {
                throw McapBytes.error(reader.path(), summaryStart, "summary section of " + summaryBytes
                        + " bytes is larger than the reader's limit of " + McapReader.MAX_RECORD_MIB + " MiB");
            }
            byte[] bytes = new byte[(int) summaryBytes + McapBytes.FOOTER_BYTES - 4];
            if (!McapBytes.readFully(ch, summaryStart, bytes, 0, bytes.length)) {
                throw McapBytes.error(reader.path(), summaryStart, "file shrank while being read");
            }
            if (recordedCrc != 0) {
                CRC32 actual = new CRC32();
                actual.update(bytes, 0, bytes.length);
                if (actual.getValue() != recordedCrc) {
                    throw McapBytes.error(reader.path(), summaryStart, String.format(
                            "summary CRC %08x differs from the recorded %08x", actual.getValue(), recordedCrc));
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
        RecordCursor c = new RecordCursor(reader.path(), bytes, 0, length, "the summary at byte " + summaryStart);
        while (c.at < c.limit) {
            int opcode = c.u8();
            long recordLength = c.u64();
            c.need(recordLength);
            int end = c.at + (int) recordLength;
            RecordCursor r = c.inner(end);
            switch (opcode) {
                case Opcode.SCHEMA -> schemas.add(r.schema());
                case Opcode.CHANNEL -> channels.add(r.channel());
                case Opcode.CHUNK_INDEX -> chunkIndexes++;
                case Opcode.STATISTICS -> statistics = r.statistics();
                default -> {
                    // summary offsets, metadata and attachment indexes
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
    String profile() throws IOException {
        try (FileChannel ch = FileChannel.open(reader.path(), StandardOpenOption.READ)) {
            byte[] head = new byte[McapBytes.RECORD_HEAD];
            long at = Opcode.MAGIC.length;
            if (!McapBytes.readFully(ch, at, head, 0, McapBytes.RECORD_HEAD) || head[0] != Opcode.HEADER) {
                throw McapBytes.error(reader.path(), at, "no header record after the magic");
            }
            long length = McapBytes.u64(head, 1);
            if (length < 0 || length > Math.min(McapBytes.MAX_RECORD_BYTES, reader.sizeBytes() - at - McapBytes.RECORD_HEAD)) {
                throw McapBytes.error(reader.path(), at, "header record of " + Long.toUnsignedString(length)
                        + " bytes overruns the file");
            }
            byte[] body = new byte[(int) length];
            if (!McapBytes.readFully(ch, at + McapBytes.RECORD_HEAD, body, 0, body.length)) {
                throw McapBytes.error(reader.path(), at, "file ends inside the header record");
            }
            return new RecordCursor(reader.path(), body, 0, body.length, "the header record").string();
        }
    }

    /** A summary made by reading the data section (a file without a summary section). */
    private McapSummary scan(String profile) throws IOException {
        List<McapSchema> schemas = new ArrayList<>();
        List<McapChannel> channels = new ArrayList<>();
        Map<Integer, Long> counts = new LinkedHashMap<>();
        long[] totals = {0, Long.MAX_VALUE, Long.MIN_VALUE, 0, 0};
        reader.read(new McapVisitor() {
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
}
