package io.rtaware.record;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.robot.msg.MediatorDecision;
import io.rtaware.ros2msg.Ros2Header;
import io.rtaware.ros2msg.cdr.CdrException;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.cdr.CdrWriter;
import org.junit.jupiter.api.Test;

/** The mediator's decision as {@code rtaware_msgs/msg/MediatorDecision}: its constants and its bytes. */
class MediatorDecisionCodecTest {

    @Test
    void theWinnerIsOneByteNamedByTheTypesConstants() {
        MediatorDecisionCodec codec = (MediatorDecisionCodec) RosCodecs.forType(MediatorDecision.class);
        String schema = codec.type().schemaText();
        // Foxglove's State Transitions panel names a value by the constants just before its field.
        assertTrue(schema.contains("uint8 OBSTACLE=" + MediatorDecision.OBSTACLE + "\nuint8 WAYPOINT="
                + MediatorDecision.WAYPOINT + "\nuint8 IDLE_STOP=" + MediatorDecision.IDLE_STOP + "\nuint8 STALE_STOP="
                + MediatorDecision.STALE_STOP + "\n"), schema);
        assertTrue(schema.endsWith("uint8 winner\n"), schema);
        MediatorDecision value = new MediatorDecision();
        value.winner = MediatorDecision.STALE_STOP;
        CdrWriter out = new CdrWriter(16);
        codec.encode(new Ros2Header(), value, out);
        assertEquals(5, out.size(), "encapsulation header and one byte");
        assertEquals(3, out.buffer()[4]);
        MediatorDecision back = new MediatorDecision();
        codec.decode(new CdrReader().wrap(out.buffer(), 0, out.size()), new Ros2Header(), back);
        assertEquals(MediatorDecision.STALE_STOP, back.winner);

        out.buffer()[4] = 4;
        CdrException e = assertThrows(CdrException.class,
                () -> codec.decode(new CdrReader().wrap(out.buffer(), 0, out.size()), new Ros2Header(), back));
        assertEquals("MediatorDecision winner 4 is none of its constants (0 to 3)", e.getMessage());
    }
}
