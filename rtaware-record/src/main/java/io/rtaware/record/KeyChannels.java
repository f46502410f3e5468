package io.rtaware.record;

import io.rtaware.core.data.Key;
import io.rtaware.core.data.StateValue;
import io.rtaware.record.encode.JsonStateCodec;
import io.rtaware.record.encode.TimingTypes;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.ros2msg.Ros2Codec;
import io.rtaware.ros2msg.Ros2Types;
import java.io.IOException;
import java.util.Map;

/**
 * The channels of one recorded key and how its values are encoded on them, every one CDR: a key
 * with a standard ROS 2 type on its topic as that type, plus what the ROS 2 message lacks on
 * {@code /rtaware/state/<key>} as an {@code rtaware_msgs/msg/StateJson} (so a value can be
 * rebuilt exactly); any other key on its topic as a StateJson alone. A ROS 2 message's header is
 * stamped with the commit's log time (world time plus the plan's log-time offset). An odometry
 * key the plan names ({@link RecordingPlan#transformsFrom}) is written as a transform on
 * {@code /tf} too. Encoding runs on the writer thread.
 */
final class KeyChannels {

    @SuppressWarnings("rawtypes")
    private final Ros2Codec ros;
    private final JsonStateCodec jsonCodec;
    private final String keyName;
    private final String frame;
    private final long stampOffsetNs;
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
        ros = RosCodecs.forType(key.type());
        String topic = plan.topicOf(key.name());
        Ros2Channels.Qos qos = plan.isLatched(key.name()) ? Ros2Channels.Qos.RELIABLE_TRANSIENT_LOCAL
                : Ros2Channels.Qos.RELIABLE_VOLATILE;
        if (ros != null) {
            channel = layout.add(topic, ros.type().name(), ros.type().schemaText(), ros.type().typeHash(), qos,
                    Map.of("key", key.name(), "frame_id", frame, RunRecorder.SEQUENCE, RunRecorder.SEQUENCE_GENERATION));
            jsonCodec = new JsonStateCodec(key.type(), true);
            stateChannel = layout.add(RecordingPlan.STATE_PREFIX + key.name(), TimingTypes.STATE_JSON.name(),
                    TimingTypes.STATE_JSON.schemaText(), null, qos, Map.of("key", key.name(), RunRecorder.SEQUENCE,
                            RunRecorder.SEQUENCE_GENERATION, StateJsonMessage.VALUE_ENCODING, StateJsonMessage.JSON,
                            "json_schema", jsonCodec.jsonSchema()));
        } else {
            jsonCodec = new JsonStateCodec(key.type(), false);
            channel = layout.add(topic, TimingTypes.STATE_JSON.name(), TimingTypes.STATE_JSON.schemaText(), null, qos,
                    Map.of("key", key.name(), RunRecorder.SEQUENCE, RunRecorder.SEQUENCE_GENERATION,
                            StateJsonMessage.VALUE_ENCODING, StateJsonMessage.JSON, "value_type", key.type().getName(),
                            "json_schema", jsonCodec.jsonSchema()));
            stateChannel = 0;
        }
        String[] tf = plan.transformsOf(key.name());
        if (tf != null && key.type() == Odometry.class) {
            tfParent = tf[0];
            tfChild = tf[1];
            tfChannel = layout.add(RecordingPlan.TF_TOPIC, Ros2Types.TF_MESSAGE.name(), Ros2Types.TF_MESSAGE.schemaText(),
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
        if (ros != null) {
            scratch.header.set(stampOffsetNs + timeNs, frame);
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
            TransformEncoder.begin(scratch.cdr, 1);
            TransformEncoder.transform(scratch.cdr, stampOffsetNs + timeNs, tfParent, tfChild, odometry.xM,
                    odometry.yM, odometry.yawRad);
            sink.write(tfChannel, generation, timeNs, timeNs, scratch.cdr.buffer(), 0, scratch.cdr.size());
        }
    }
}
