package io.rtaware.record;

import io.rtaware.core.data.Key;
import io.rtaware.core.data.StateValue;
import io.rtaware.record.encode.JsonStateCodec;
import io.rtaware.record.mcap.McapWriter;
import io.rtaware.ros2msg.Ros2Codec;
import java.io.IOException;
import java.util.Map;

/**
 * The channels of one recorded key and how its values are encoded on them: a key with a standard
 * ROS 2 type on its topic as CDR, plus what the ROS 2 message lacks on
 * {@code /rtaware/state/<key>} (so a value can be rebuilt exactly); any other key on its topic
 * alone. Encoding runs on the writer thread.
 */
final class KeyChannels {

    @SuppressWarnings("rawtypes")
    private final Ros2Codec ros;
    private final JsonStateCodec jsonCodec;
    private final String frame;
    private final int channel;
    private final int stateChannel;

    KeyChannels(Key<?> key, RecordingPlan plan, McapWriter writer) throws IOException {
        frame = plan.frameOf(key.name());
        ros = RosCodecs.forType(key.type());
        String topic = plan.topicOf(key.name());
        if (ros != null) {
            int schema = writer.addSchema(ros.type().name(), "ros2msg", ros.type().schemaText());
            channel = writer.addChannel(schema, topic, "cdr", Map.of("key", key.name(), "frame_id", frame,
                    RunRecorder.SEQUENCE, RunRecorder.SEQUENCE_GENERATION));
            jsonCodec = new JsonStateCodec(key.type(), true);
            int stateSchema = writer.addSchema("rtaware/state/" + key.type().getSimpleName(), "jsonschema",
                    jsonCodec.jsonSchema());
            stateChannel = writer.addChannel(stateSchema, RecordingPlan.STATE_PREFIX + key.name(), "json",
                    Map.of("key", key.name(), RunRecorder.SEQUENCE, RunRecorder.SEQUENCE_GENERATION));
        } else {
            jsonCodec = new JsonStateCodec(key.type(), false);
            int schema = writer.addSchema(key.type().getName(), "jsonschema", jsonCodec.jsonSchema());
            channel = writer.addChannel(schema, topic, "json", Map.of("key", key.name(), RunRecorder.SEQUENCE,
                    RunRecorder.SEQUENCE_GENERATION));
            stateChannel = 0;
        }
    }

    /** Writer thread: encodes one committed value on the key's channels. */
    @SuppressWarnings("unchecked")
    void write(StateValue<?> value, long generation, long timeNs, MessageSink sink, WriterScratch scratch)
            throws IOException {
        if (ros != null) {
            scratch.header.set(timeNs, frame);
            ros.encode(scratch.header, value, scratch.cdr);
            sink.write(channel, generation, timeNs, timeNs, scratch.cdr.buffer(), 0, scratch.cdr.size());
        }
        scratch.json.clear();
        jsonCodec.encode(value, scratch.json);
        sink.write(ros != null ? stateChannel : channel, generation, timeNs, timeNs, scratch.json.array(), 0,
                scratch.json.size());
    }
}
