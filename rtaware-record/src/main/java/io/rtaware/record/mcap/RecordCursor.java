package io.rtaware.record.mcap;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The lexer of one record's bytes: bounded little-endian fields (a length is checked against what
 * is left of the record before anything is read or allocated for it), and the records the reader
 * hands over parsed from them. Errors name the file and the record's place in it.
 */
final class RecordCursor {

    final byte[] data;
    int at;
    final int limit;
    private final Path file;
    final String where;

    /**
     * @param file the file, for errors
     * @param data the bytes
     * @param from the record's first byte
     * @param limit one past its last
     * @param where the record's place, for errors ({@code the chunk at byte 28})
     */
    RecordCursor(Path file, byte[] data, int from, int limit, String where) {
        this.file = file;
        this.data = data;
        this.at = from;
        this.limit = limit;
        this.where = where;
    }

    /** @return a cursor over the next {@code end - at} bytes of the same array, for a nested record */
    RecordCursor inner(int end) {
        return new RecordCursor(file, data, at, end, where);
    }

    void need(long n) throws McapFormatException {
        if (n < 0 || n > limit - at) {
            throw new McapFormatException(file + ": record field of " + n + " bytes overruns its record ("
                    + (limit - at) + " left) in " + where);
        }
    }

    int u8() throws McapFormatException {
        need(1);
        return data[at++] & 0xff;
    }

    int u16() throws McapFormatException {
        need(2);
        int v = (short) McapBytes.I16.get(data, at) & 0xffff;
        at += 2;
        return v;
    }

    long u32() throws McapFormatException {
        need(4);
        long v = (int) McapBytes.I32.get(data, at) & 0xffffffffL;
        at += 4;
        return v;
    }

    long u64() throws McapFormatException {
        need(8);
        long v = (long) McapBytes.I64.get(data, at);
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
        RecordCursor entries = inner(end);
        while (entries.at < end) {
            map.put(entries.string(), entries.string());
        }
        at = end;
        return map;
    }

    /** @return the schema record at the cursor */
    McapSchema schema() throws McapFormatException {
        int id = u16();
        String name = string();
        String encoding = string();
        long n = u32();
        need(n);
        String schemaData = new String(data, at, (int) n, StandardCharsets.UTF_8);
        at += (int) n;
        return new McapSchema(id, name, encoding, schemaData);
    }

    /** @return the channel record at the cursor */
    McapChannel channel() throws McapFormatException {
        return new McapChannel(u16(), u16(), string(), string(), stringMap());
    }

    /** @return the statistics record at the cursor (its attachment count is not kept) */
    McapStatistics statistics() throws McapFormatException {
        long messages = u64();
        int schemas = u16();
        long channels = u32();
        u32(); // attachments
        long metadata = u32();
        long chunks = u32();
        long start = u64();
        long end = u64();
        long n = u32();
        need(n);
        Map<Integer, Long> counts = new LinkedHashMap<>();
        int stop = at + (int) n;
        while (at < stop) {
            counts.put(u16(), u64());
        }
        return new McapStatistics(messages, schemas, channels, metadata, chunks, start, end, counts);
    }
}
