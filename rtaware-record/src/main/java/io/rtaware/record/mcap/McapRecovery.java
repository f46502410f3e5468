package io.rtaware.record.mcap;

import java.io.IOException;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;

/**
 * Recovers what an unfinished or damaged MCAP file holds (a recording whose run was killed, or
 * whose disk filled up): every schema, channel and metadata record and every message of every
 * complete chunk, up to the first record that cannot be read, written to a new, finished file.
 */
public final class McapRecovery {

    /**
     * What a recovery found.
     *
     * @param messages messages written to the new file
     * @param chunks complete chunks read
     * @param firstLogTimeNs earliest log time recovered (0 without messages)
     * @param lastLogTimeNs latest log time recovered (0 without messages)
     * @param goodBytes bytes of the damaged file read up to the first unreadable record
     * @param fileBytes the damaged file's size
     * @param problem why the rest could not be read, or null if nothing was lost
     */
    public record Result(long messages, long chunks, long firstLogTimeNs, long lastLogTimeNs, long goodBytes,
                         long fileBytes, String problem) {

        /** @return bytes of the damaged file that could not be recovered */
        public long lostBytes() {
            return fileBytes - goodBytes;
        }
    }

    private McapRecovery() {
    }

    /**
     * @param damaged the file to recover (its leading magic is required)
     * @param recovered the new file (created or truncated)
     * @return what was recovered and what was lost
     * @throws IOException if the damaged file is not MCAP at all or the new one cannot be written
     */
    public static Result recover(Path damaged, Path recovered) throws IOException {
        McapReader reader = McapReader.openUnfinished(damaged);
        String profile = reader.profile();
        Map<Integer, Integer> schemas = new HashMap<>();
        Map<Integer, Integer> channels = new HashMap<>();
        long[] counts = {0, 0, Long.MAX_VALUE, Long.MIN_VALUE};
        IOException[] failure = {null};
        McapReader.ReadEnd end;
        try (McapWriter writer = new McapWriter(recovered, Compression.ZSTD, McapWriter.DEFAULT_CHUNK_BYTES, profile)) {
            end = reader.readRecoverable(new McapVisitor() {
                @Override
                public void schema(McapSchema schema) {
                    if (failure[0] == null && !schemas.containsKey(schema.id())) {
                        try {
                            schemas.put(schema.id(), writer.addSchema(schema.name(), schema.encoding(), schema.data()));
                        } catch (IOException e) {
                            failure[0] = e;
                        }
                    }
                }

                @Override
                public void channel(McapChannel channel) {
                    if (failure[0] == null && !channels.containsKey(channel.id())) {
                        try {
                            int schema = channel.schemaId() == 0 ? 0 : schemas.getOrDefault(channel.schemaId(), -1);
                            if (schema < 0) {
                                return; // its schema was never written: its messages cannot be decoded
                            }
                            channels.put(channel.id(), writer.addChannel(schema, channel.topic(),
                                    channel.messageEncoding(), channel.metadata()));
                        } catch (IOException e) {
                            failure[0] = e;
                        }
                    }
                }

                @Override
                public void metadata(String name, Map<String, String> entries) {
                    if (failure[0] == null) {
                        try {
                            writer.addMetadata(name, entries);
                        } catch (IOException e) {
                            failure[0] = e;
                        }
                    }
                }

                @Override
                public void chunk(long fileOffset, long startNs, long endNs) {
                    counts[1]++;
                }

                @Override
                public void message(McapChannel channel, long sequence, long logTimeNs, long publishTimeNs,
                                    byte[] data, int offset, int length) {
                    Integer id = channels.get(channel.id());
                    if (failure[0] != null || id == null) {
                        return;
                    }
                    try {
                        writer.writeMessage(id, sequence, logTimeNs, publishTimeNs, data, offset, length);
                        counts[0]++;
                        counts[2] = Math.min(counts[2], logTimeNs);
                        counts[3] = Math.max(counts[3], logTimeNs);
                    } catch (IOException e) {
                        failure[0] = e;
                    }
                }
            });
            if (failure[0] != null) {
                throw failure[0];
            }
        }
        boolean any = counts[0] > 0;
        return new Result(counts[0], counts[1], any ? counts[2] : 0, any ? counts[3] : 0, end.goodBytes(),
                reader.sizeBytes(), end.problem());
    }
}
