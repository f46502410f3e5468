package io.rtaware.ros2.graph;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Several publishers on one topic, told apart by the rmw_zenoh gid, on stepped time. */
class FirstPublisherFilterTest {

    private static final long MS = 1_000_000L;
    private static final long SILENCE_NS = 1000 * MS;

    private final List<String> reports = new ArrayList<>();
    private final FirstPublisherFilter filter = new FirstPublisherFilter("/robot1/odom", SILENCE_NS, reports::add);
    private final ByteBuffer attachment = ByteBuffer.allocateDirect(SampleAttachment.BYTES).order(ByteOrder.LITTLE_ENDIAN);

    private static byte[] gid(int b) {
        byte[] gid = new byte[SampleAttachment.GID_BYTES];
        gid[0] = (byte) b;
        gid[15] = (byte) (b * 3);
        return gid;
    }

    private boolean from(byte[] gid, long nowNs) {
        SampleAttachment.write(attachment, 1, 0, gid);
        return filter.accept(attachment, SampleAttachment.BYTES, nowNs);
    }

    @Test
    void theFirstPublisherIsFollowedAndEachOtherIsReportedOnceAndDropped() {
        byte[] first = gid(1);
        byte[] second = gid(2);
        byte[] third = gid(3);
        for (int i = 0; i < 50; i++) {
            long nowNs = i * 20 * MS;
            assertTrue(from(first, nowNs), "the first publisher, sample " + i);
            assertFalse(from(second, nowNs), "the second publisher, sample " + i);
            if (i % 10 == 0) {
                assertFalse(from(third, nowNs), "the third publisher, sample " + i);
            }
        }
        assertEquals(55, filter.ignored());
        assertEquals(List.of(
                "/robot1/odom: another publisher (gid " + HexFormat.of().formatHex(second) + ") besides the one followed"
                        + " (gid " + HexFormat.of().formatHex(first) + "); its samples are dropped",
                "/robot1/odom: another publisher (gid " + HexFormat.of().formatHex(third) + ") besides the one followed"
                        + " (gid " + HexFormat.of().formatHex(first) + "); its samples are dropped"), reports);
    }

    @Test
    void anotherPublisherIsFollowedOnlyAfterTheFollowedOneWasSilentForTheWholeSpan() {
        byte[] driver = gid(1);
        byte[] restarted = gid(9);
        assertTrue(from(driver, 0));
        assertFalse(from(restarted, SILENCE_NS - 1), "one nanosecond short of the silence");
        assertTrue(from(restarted, SILENCE_NS), "the followed publisher silent for exactly the span");
        assertFalse(from(driver, SILENCE_NS + 20 * MS), "the old publisher is now the other one");
        assertEquals(2, filter.ignored());
        assertEquals(3, reports.size(), reports.toString());
        assertEquals("/robot1/odom: publisher gid " + HexFormat.of().formatHex(driver) + " silent for 1.0 s; following "
                + "publisher gid " + HexFormat.of().formatHex(restarted), reports.get(1));
    }

    @Test
    void samplesWithoutAnRmwZenohAttachmentAreLetThrough() {
        assertTrue(from(gid(1), 0));
        assertTrue(filter.accept(attachment, -1, 0), "no attachment");
        assertTrue(filter.accept(attachment, 12, 0), "not the rmw_zenoh form");
        assertEquals(0, filter.ignored());
        assertThrows(IllegalArgumentException.class, () -> new FirstPublisherFilter("t", 0, reports::add));
    }
}
