package io.rtaware.ros2msg;

import io.rtaware.ros2msg.cdr.CdrException;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.cdr.CdrWriter;
import io.rtaware.ros2msg.value.DiagnosticArray;
import io.rtaware.ros2msg.value.DiagnosticStatus;

/**
 * {@link DiagnosticArray} as {@code diagnostic_msgs/msg/DiagnosticArray}. Decoding rejects more
 * statuses, or more values in a status, than the target's capacity.
 */
public final class DiagnosticArrayCodec implements Ros2Codec<DiagnosticArray> {

    /** Least bytes of one DiagnosticStatus: level 1, three strings of 5 bytes at least, values length 4. */
    private static final int MIN_STATUS_BYTES = 1 + 3 * 5 + 4;
    /** Least bytes of one KeyValue: two strings of 5 bytes at least. */
    private static final int MIN_KEY_VALUE_BYTES = 2 * 5;

    @Override
    public Ros2MessageType type() {
        return Ros2Types.DIAGNOSTIC_ARRAY;
    }

    @Override
    public void encode(Ros2Header header, DiagnosticArray value, CdrWriter out) {
        out.begin();
        Fields.writeHeader(out, header);
        out.writeSequenceLength(value.count());
        for (int i = 0; i < value.count(); i++) {
            DiagnosticStatus s = value.status(i);
            out.writeInt8(s.level);
            out.writeString(s.name);
            out.writeString(s.message);
            out.writeString(s.hardwareId);
            out.writeSequenceLength(s.valueCount());
            for (int k = 0; k < s.valueCount(); k++) {
                out.writeString(s.key(k));
                out.writeString(s.value(k));
            }
        }
    }

    @Override
    public void decode(CdrReader in, Ros2Header header, DiagnosticArray into) {
        Fields.readHeader(in, header);
        int n = in.readSequenceLength(MIN_STATUS_BYTES);
        if (n > into.capacity()) {
            throw new CdrException("DiagnosticArray of " + n + " statuses exceeds the capacity of " + into.capacity());
        }
        into.clear();
        for (int i = 0; i < n; i++) {
            DiagnosticStatus s = into.add();
            s.level = in.readInt8();
            in.readString(s.name);
            in.readString(s.message);
            in.readString(s.hardwareId);
            int values = in.readSequenceLength(MIN_KEY_VALUE_BYTES);
            if (values > s.valueCapacity()) {
                throw new CdrException("DiagnosticStatus of " + values + " values exceeds the capacity of "
                        + s.valueCapacity());
            }
            for (int k = 0; k < values; k++) {
                int index = s.addValue();
                in.readString(s.key(index));
                in.readString(s.value(index));
            }
        }
    }
}
