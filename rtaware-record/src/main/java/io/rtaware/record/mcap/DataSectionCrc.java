package io.rtaware.record.mcap;

import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.file.Path;
import java.util.zip.CRC32;

/**
 * The CRC of a finished file's data section, recorded in its data-end record just before the
 * summary (or the footer), checked over the bytes as stored, so that a damaged compressed chunk
 * is named before a decompressor sees it.
 */
final class DataSectionCrc {

    private static final int BLOCK = 1 << 20;

    private DataSectionCrc() {
    }

    /**
     * Checks it; does nothing when the data-end record is not where a writer puts it or records
     * no CRC (the sequential pass then checks what it can).
     *
     * @param file the file, for errors
     * @param ch the file open for reading
     * @param size its size
     * @throws IOException if the CRC differs or the file shrank
     */
    static void check(Path file, FileChannel ch, long size) throws IOException {
        long footerAt = size - Opcode.MAGIC.length - McapBytes.FOOTER_BYTES;
        byte[] footer = new byte[McapBytes.FOOTER_BYTES];
        if (!McapBytes.readFully(ch, footerAt, footer, 0, McapBytes.FOOTER_BYTES) || footer[0] != Opcode.FOOTER) {
            return;
        }
        long summaryStart = McapBytes.u64(footer, McapBytes.RECORD_HEAD);
        long dataEndAt = (summaryStart == 0 ? footerAt : summaryStart) - McapBytes.DATA_END_BYTES;
        if (dataEndAt < Opcode.MAGIC.length || dataEndAt > footerAt) {
            return;
        }
        byte[] dataEnd = new byte[McapBytes.DATA_END_BYTES];
        if (!McapBytes.readFully(ch, dataEndAt, dataEnd, 0, McapBytes.DATA_END_BYTES) || dataEnd[0] != Opcode.DATA_END
                || McapBytes.u64(dataEnd, 1) != 4) {
            return;
        }
        long recorded = McapBytes.u32(dataEnd, McapBytes.RECORD_HEAD);
        if (recorded == 0) {
            return;
        }
        CRC32 crc = new CRC32();
        byte[] block = new byte[(int) Math.min(BLOCK, dataEndAt)];
        for (long at = 0; at < dataEndAt; ) {
            int n = (int) Math.min(block.length, dataEndAt - at);
            if (!McapBytes.readFully(ch, at, block, 0, n)) {
                throw McapBytes.error(file, at, "file shrank while being read");
            }
            crc.update(block, 0, n);
            at += n;
        }
        if (crc.getValue() != recorded) {
            throw McapBytes.error(file, dataEndAt, String.format("data section CRC %08x differs from the recorded %08x"
                    + " (the file is damaged)", crc.getValue(), recorded));
        }
    }
}
