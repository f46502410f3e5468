package io.rtaware.ros2msg;

import io.rtaware.ros2msg.cdr.CdrException;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.cdr.CdrWriter;
import io.rtaware.ros2msg.value.MetricsMessage;

/**
 * {@link MetricsMessage} as {@code statistics_msgs/msg/MetricsMessage}. The type has no header: the
 * {@link Ros2Header} of {@link #encode} and {@link #decode} is left alone; the window's stamps are
 * the message's own. Encoding refuses an infinite data point (ROS 2's statistics are finite or
 * NaN, NaN meaning "no sample"); decoding rejects more data points than the target's capacity.
 */
public final class MetricsMessageCodec implements Ros2Codec<MetricsMessage> {

    /** Least bytes of one StatisticDataPoint: data_type 1, data 8 (when no padding falls between). */
    private static final int MIN_POINT_BYTES = 1 + 8;

    @Override
    public Ros2MessageType type() {
        return Ros2Types.METRICS_MESSAGE;
    }

    @Override
    public void encode(Ros2Header header, MetricsMessage value, CdrWriter out) {
        for (int i = 0; i < value.count(); i++) {
            if (Double.isInfinite(value.data(i))) {
                throw new CdrException("MetricsMessage data point " + i + " of " + value.measurementSourceName + " "
                        + value.metricsSource + " is " + value.data(i) + ": statistics are finite or NaN");
            }
        }
        out.begin();
        out.writeString(value.measurementSourceName);
        out.writeString(value.metricsSource);
        out.writeString(value.unit);
        Fields.writeTime(out, value.windowStartNs);
        Fields.writeTime(out, value.windowStopNs);
        out.writeSequenceLength(value.count());
        for (int i = 0; i < value.count(); i++) {
            out.writeInt8(value.dataType(i));
            out.writeFloat64(value.data(i));
        }
    }

    @Override
    public void decode(CdrReader in, Ros2Header header, MetricsMessage into) {
        into.clear();
        in.readString(into.measurementSourceName);
        in.readString(into.metricsSource);
        in.readString(into.unit);
        into.windowStartNs = Fields.readTime(in);
        into.windowStopNs = Fields.readTime(in);
        int n = in.readSequenceLength(MIN_POINT_BYTES);
        if (n > into.capacity()) {
            throw new CdrException("MetricsMessage of " + n + " data points exceeds the capacity of "
                    + into.capacity());
        }
        for (int i = 0; i < n; i++) {
            byte dataType = in.readInt8();
            into.add(dataType, in.readFloat64());
        }
    }
}
