package io.rtaware.record;

import io.rtaware.record.encode.TimingTypes;
import io.rtaware.robot.msg.MediatorDecision;
import io.rtaware.ros2msg.Ros2Codec;
import io.rtaware.ros2msg.Ros2Header;
import io.rtaware.ros2msg.Ros2MessageType;
import io.rtaware.ros2msg.cdr.CdrException;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.cdr.CdrWriter;

/**
 * {@link MediatorDecision} as {@code rtaware_msgs/msg/MediatorDecision}, whose constants name the
 * winners (so Foxglove's State Transitions panel labels them). Decoding rejects a winner that is
 * none of them. Allocates nothing.
 */
final class MediatorDecisionCodec implements Ros2Codec<MediatorDecision> {

    @Override
    public Ros2MessageType type() {
        return TimingTypes.MEDIATOR_DECISION;
    }

    @Override
    public void encode(Ros2Header header, MediatorDecision value, CdrWriter out) {
        out.begin();
        out.writeInt8(value.winner);
    }

    @Override
    public void decode(CdrReader in, Ros2Header header, MediatorDecision into) {
        int winner = in.readInt8() & 0xFF;
        if (winner > MediatorDecision.STALE_STOP) {
            throw new CdrException("MediatorDecision winner " + winner + " is none of its constants (0 to 3)");
        }
        into.winner = winner;
    }
}
