package io.rtaware.ros2.graph;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.util.HexFormat;
import org.junit.jupiter.api.Test;

class SampleAttachmentTest {

    @Test
    void layoutIsSequenceTimestampGidLengthGid() {
        byte[] gid = new byte[16];
        for (int i = 0; i < 16; i++) {
            gid[i] = (byte) (0xa0 + i);
        }
        ByteBuffer b = ByteBuffer.allocate(SampleAttachment.BYTES);
        SampleAttachment.write(b, 2, 0x0102030405060708L, gid);
        assertEquals("0200000000000000" + "0807060504030201" + "10" + "a0a1a2a3a4a5a6a7a8a9aaabacadaeaf",
                HexFormat.of().formatHex(b.array()));
        assertTrue(SampleAttachment.valid(b, 33));
        assertEquals(2, SampleAttachment.sequence(b));
        assertEquals(0x0102030405060708L, SampleAttachment.sourceTimestampNs(b));
    }

    @Test
    void otherLengthsAreNotRmwZenohAttachments() {
        ByteBuffer b = ByteBuffer.allocate(64);
        SampleAttachment.write(b, 1, 1, new byte[16]);
        assertFalse(SampleAttachment.valid(b, 32));
        assertFalse(SampleAttachment.valid(b, -1));
        b.put(16, (byte) 8);
        assertFalse(SampleAttachment.valid(b, 33));
    }
}
