package io.rtaware.record;

import io.rtaware.core.data.Key;
import io.rtaware.core.data.StateValue;
import io.rtaware.record.encode.JsonStateCodec;
import io.rtaware.record.encode.TimingTypes;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.ros2msg.RobotTopics;
import io.rtaware.ros2msg.Ros2Codec;
import io.rtaware.ros2msg.Ros2Types;
import io.rtaware.ros2msg.TransformMessages;
import java.io.IOException;
import java.util.Map;

/**
 * The channels of one recorded key and how its values are encoded on them, every one CDR: a key
 * with a standard ROS 2 type on its topic as that type, plus what the ROS 2 message lacks on
 * {@code /rtaware/state/<key>} as an {@code rtaware_msgs/msg/StateJson} (so a value can be
 * rebuilt exactly); any other key on its topic as a StateJson alone. A ROS 2 message's header is
 * stamped with the time its data was measured where the plan knows the robot's clock
 * ({@link RecordingPlan#robotClockOriginNs(long)}: a scan's and an odometry sample's own
 * timestamp, mapped to world time), else with the commit's; both plus the plan's log-time
 * offset, like log times. An odometry key the plan names ({@link RecordingPlan#transformsFrom})
 * is written as a transform on {@code /tf} too, stamped as its message. Encoding runs on the
 * writer thread.
 */
final class KeyChannels {

    @SuppressWarnings("rawtypes")
    private final Ros2Codec ros;
    private final JsonStateCodec jsonCodec;
    private final String keyName;
    private final String frame;
    private final long stampOffsetNs;
    /** True if scans and odometry are stamped when measured. */
    private final boolean measured;
    /** Added to a robot's timestamp in ns to make a stamp: the log-time offset plus its clock's origin. */
    private final long robotStampOffsetNs;
    private final int channel;
    private final int stateChannel;
    /** The /tf channel an odometry key's commits are also written to, or 0. */
    private final int tfChannel;
    private final String tfParent;
    private final String tfChild;

    KeyChannels(Key<?> key, RecordingPlan plan, Ros2Channels layout) throws IOException {
        keyName = key.name();
        frame = plan.frameOf(key.name());
        stampOffsetNs = plan.logTimeOffsetNs();
        measured = plan.robotClockKnown();
        robotStampOffsetNs = plan.logTimeOffsetNs() + plan.robotClockOriginNs();
        ros = RosCodecs.forType(key.type());
        String topic = plan.topicOf(key.name());
        Ros2Channels.Qos qos = plan.isLatched(key.name()) ? Ros2Channels.Qos.RELIABLE_TRANSIENT_LOCAL
                : Ros2Channels.Qos.RELIABLE_VOLATILE;
        if (ros != null) {
            channel = layout.add(topic, ros.type().name(), ros.type().schemaText(), ros.type().typeHash(), qos,
                    Map.of("key", key.name(), "frame_id", frame, RunRecorder.SEQUENCE, RunRecorder.SEQUENCE_GENERATION));
            jsonCodec = new JsonStateCodec(key.type(), true);
            stateChannel = layout.add(RecordingPlan.STATE_PREFIX + key.name(), TimingTypes.STATE_JSON.name(),
                    TimingTypes.STATE_JSON.schemaText(), TimingTypes.STATE_JSON.typeHash(), qos, Map.of("key",
                            key.name(), RunRecorder.SEQUENCE, RunRecorder.SEQUENCE_GENERATION,
                            StateJsonMessage.VALUE_ENCODING, StateJsonMessage.JSON, "json_schema", jsonCodec.jsonSchema()));
        } else {
            jsonCodec = new JsonStateCodec(key.type(), false);
            channel = layout.add(topic, TimingTypes.STATE_JSON.name(), TimingTypes.STATE_JSON.schemaText(),
                    TimingTypes.STATE_JSON.typeHash(), qos, Map.of("key", key.name(), RunRecorder.SEQUENCE,
                            RunRecorder.SEQUENCE_GENERATION, StateJsonMessage.VALUE_ENCODING, StateJsonMessage.JSON,
                            "value_type", key.type().getName(), "json_schema", jsonCodec.jsonSchema()));
            stateChannel = 0;
        }
        String[] tf = plan.transformsOf(key.name());
        if (tf != null && key.type() == Odometry.class) {
            tfParent = tf[0];
            tfChild = tf[1];
            tfChannel = layout.add(RobotTopics.TF, Ros2Types.TF_MESSAGE.name(), Ros2Types.TF_MESSAGE.schemaText(),
                    Ros2Types.TF_MESSAGE.typeHash(), Ros2Channels.Qos.TF, Map.of());
        } else {
            tfParent = null;
            tfChild = null;
            tfChannel = 0;
        }
    }

    /** Writer thread: encodes one committed value on the key's channels. */
    @SuppressWarnings("unchecked")
    void write(StateValue<?> value, long generation, long timeNs, MessageSink sink, WriterScratch scratch)
            throws IOException {
        long stampNs = stampNs(value, timeNs);
        if (ros != null) {
            scratch.header.set(stampNs, frame);
            ros.encode(scratch.header, value, scratch.cdr);
            sink.write(channel, generation, timeNs, timeNs, scratch.cdr.buffer(), 0, scratch.cdr.size());
        }
        scratch.json.clear();
        jsonCodec.encode(value, scratch.json);
        StateJsonMessage.encode(scratch.cdr, keyName, scratch.json.array(), scratch.json.size());
        sink.write(ros != null ? stateChannel : channel, generation, timeNs, timeNs, scratch.cdr.buffer(), 0,
                scratch.cdr.size());
        if (tfChannel != 0) {
            Odometry odometry = (Odometry) value;
            TransformMessages.begin(scratch.cdr, 1);
            TransformMessages.transform(scratch.cdr, stampNs, tfParent, tfChild, odometry.xM, odometry.yM,
                    odometry.yawRad);
            sink.write(tfChannel, generation, timeNs, timeNs, scratch.cdr.buffer(), 0, scratch.cdr.size());
        }
    }

    /**
     * @return the header stamp of a value committed at world time {@code timeNs}: when it was
     *     measured for a scan or odometry sample of a robot whose clock the plan knows, else
     *     the commit's time; Unix-epoch ns
     */
    private long stampNs(StateValue<?> value, long timeNs) {
        if (measured) {
            double measuredS = value instanceof LaserScan scan ? scan.serverTimeS
                    : value instanceof Odometry odometry ? odometry.serverTimeS : Double.NaN;
            if (Double.isFinite(measuredS)) {
                return robotStampOffsetNs + Math.round(measuredS * 1e9);
            }
        }
        return stampOffsetNs + timeNs;
    }
}
