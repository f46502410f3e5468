package io.rtaware.record.mcap;

import com.github.luben.zstd.Zstd;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Path;
import java.util.zip.CRC32;
import org.apache.commons.compress.compressors.lz4.FramedLZ4CompressorInputStream;

/**
 * Turns a chunk's stored records into its records: none, zstd or lz4, to exactly the size the
 * chunk declares, and checks the chunk's CRC over them. Keeps one buffer, grown to the largest
 * chunk seen; not thread-safe (one per pass).
 */
final class ChunkDecompressor {

    private final Path file;
    private byte[] records = new byte[0];

    /** @param file the file, for errors */
    ChunkDecompressor(Path file) {
        this.file = file;
    }

    /** @return whether the reader can decompress chunks of this MCAP compression name */
    static boolean supports(String compression) {
        return compression.isEmpty() || compression.equals(Compression.ZSTD.mcapName())
                || compression.equals(Compression.LZ4.mcapName());
    }

    /**
     * @param compression the chunk's compression name ({@link #supports} it)
     * @param stored the stored records
     * @param storedLength how many bytes of {@code stored} they are
     * @param uncompressed the size the chunk declares, within the reader's limit
     * @param recordedCrc the chunk's CRC of its records, 0 for none
     * @param chunkAt where the chunk starts, for errors
     * @return the records: {@code stored} itself when uncompressed, else this decompressor's
     *     buffer, valid until the next call
     * @throws McapFormatException if they do not decompress to the declared size or their CRC differs
     */
    byte[] records(String compression, byte[] stored, int storedLength, int uncompressed, long recordedCrc,
                   long chunkAt) throws McapFormatException {
        byte[] data;
        if (compression.isEmpty()) {
            data = stored;
        } else {
            if (records.length < uncompressed) {
                records = new byte[uncompressed];
            }
            decompress(compression, stored, storedLength, uncompressed, chunkAt);
            data = records;
        }
        if (recordedCrc != 0) {
            CRC32 actual = new CRC32();
            actual.update(data, 0, uncompressed);
            if (actual.getValue() != recordedCrc) {
                throw McapBytes.error(file, chunkAt, String.format("chunk CRC %08x differs from the recorded %08x",
                        actual.getValue(), recordedCrc));
            }
        }
        return data;
    }

    private void decompress(String compression, byte[] stored, int storedLength, int uncompressed, long chunkAt)
            throws McapFormatException {
        String problem;
        try {
            if (compression.equals(Compression.ZSTD.mcapName())) {
                long declared = Zstd.getFrameContentSize(stored, 0, storedLength);
                if (declared >= 0 && declared != uncompressed) {
                    throw McapBytes.error(file, chunkAt, "zstd chunk's frame says " + declared + " bytes, its record "
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
        throw McapBytes.error(file, chunkAt, compression + " chunk does not decompress to its " + uncompressed
                + " bytes: " + problem);
    }
}
