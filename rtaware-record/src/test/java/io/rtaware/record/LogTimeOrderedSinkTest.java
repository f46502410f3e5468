package io.rtaware.record;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The reorder window orders what comes within it; what comes after a newer message was passed on
 * is written late by a file's window (nothing lost) and dropped by a tap's (no channel goes back in
 * time), counted by both.
 */
class LogTimeOrderedSinkTest {

    private static final long OFFSET_NS = 1_000_000;

    private static List<Long> feed(boolean dropLate, long[] outOfOrder) throws IOException {
        List<Long> out = new ArrayList<>();
        LogTimeOrderedSink sink = new LogTimeOrderedSink((channel, sequence, logTimeNs, publishTimeNs, data, offset,
                length) -> out.add(logTimeNs - OFFSET_NS), dropLate, OFFSET_NS, 100, 16, 1 << 16);
        byte[] message = {1, 2, 3};
        for (long t : new long[] {0, 200, 50, 400, 100, 500}) { // 50 within the window; 100 after 200 was passed on
            sink.write(1, 0, t, t, message, 0, message.length);
        }
        sink.flush();
        outOfOrder[0] = sink.outOfOrder();
        return out;
    }

    @Test
    void aFileGetsALateMessageLateAndATapDoesNotGetIt() throws IOException {
        long[] late = new long[1];
        assertEquals(List.of(0L, 50L, 200L, 100L, 400L, 500L), feed(false, late), "the file: nothing lost");
        assertEquals(1, late[0]);
        assertEquals(List.of(0L, 50L, 200L, 400L, 500L), feed(true, late), "the tap: never back in time");
        assertEquals(1, late[0]);
    }
}
