package io.rtaware.app.replay;

import com.fasterxml.jackson.databind.ObjectMapper;
import io.rtaware.core.data.Key;
import io.rtaware.core.data.StateValue;
import io.rtaware.record.RosCodecs;
import io.rtaware.record.encode.ByteBuf;
import io.rtaware.record.encode.JsonStateCodec;
import io.rtaware.record.encode.StateFields;
import io.rtaware.ros2msg.Ros2Codec;
import io.rtaware.ros2msg.Ros2Header;
import io.rtaware.ros2msg.cdr.CdrException;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.cdr.CdrWriter;
import java.io.IOException;
import java.lang.reflect.Array;
import java.lang.reflect.Field;
import java.util.Arrays;

/**
 * One key's values in and out of a recording, as the recorder encodes them: a ROS 2-typed key
 * as CDR plus its {@code /rtaware/state/<key>} JSON, any other key as JSON. Decodes a recorded
 * commit into a value, tells whether a value encodes to the same bytes as a recorded commit, and
 * names the first field in which two values differ. Not thread-safe.
 *
 * @param <T> the value type
 */
final class ValueCodec<T extends StateValue<T>> {

    private static final ObjectMapper JSON = new ObjectMapper();

    private final Key<T> key;
    private final String frameId;
    private final Ros2Codec<T> ros;
    private final JsonStateCodec json;
    private final StateFields fields;
    private final CdrReader reader = new CdrReader();
    private final CdrWriter cdr = new CdrWriter(4 << 20);
    private final ByteBuf text = new ByteBuf(1 << 14);
    private final Ros2Header header = new Ros2Header();
    private final T recorded;
    private final T replayed;

    @SuppressWarnings("unchecked")
    ValueCodec(Key<T> key, String frameId) {
        this.key = key;
        this.frameId = frameId;
        this.ros = (Ros2Codec<T>) RosCodecs.forType(key.type());
        this.json = new JsonStateCodec(key.type(), ros != null);
        this.fields = StateFields.of(key.type());
        this.recorded = key.newBuffer();
        this.replayed = key.newBuffer();
    }

    /** @return the key */
    Key<T> key() {
        return key;
    }

    /**
     * Sets {@code into} to a recorded commit's value.
     *
     * @param commit the commit
     * @param into receives the value
     * @throws IOException naming the key and generation if the messages are malformed
     */
    void decode(Recording.Commit commit, T into) throws IOException {
        try {
            if (ros != null) {
                ros.decode(reader.wrap(commit.data(), 0, commit.data().length), header, into);
                if (commit.state() != null) {
                    json.decode(JSON.readTree(commit.state()), into);
                }
            } else {
                json.decode(JSON.readTree(commit.data()), into);
            }
        } catch (CdrException | IllegalArgumentException | IOException e) {
            throw new IOException("recorded value of '" + key.name() + "' (generation " + commit.generation()
                    + ") is not readable: " + e.getMessage());
        }
    }

    /**
     * @param value a value
     * @param commit a recorded commit
     * @return true if the value encodes to exactly the recorded messages (header stamped as recorded)
     */
    boolean sameAs(T value, Recording.Commit commit) {
        if (ros != null) {
            header.set(commit.timeNs(), frameId);
            ros.encode(header, value, cdr);
            if (!Arrays.equals(cdr.buffer(), 0, cdr.size(), commit.data(), 0, commit.data().length)) {
                return false;
            }
            if (commit.state() == null) {
                return true;
            }
            text.clear();
            json.encode(value, text);
            return Arrays.equals(text.array(), 0, text.size(), commit.state(), 0, commit.state().length);
        }
        text.clear();
        json.encode(value, text);
        return Arrays.equals(text.array(), 0, text.size(), commit.data(), 0, commit.data().length);
    }

    /**
     * Names where a value differs from a recorded commit, comparing both as the recording carries
     * them (the value is encoded and decoded again, so a lossy encoding treats both alike).
     *
     * @param value the replayed value
     * @param commit the recorded commit
     * @return the field, value recorded and value replayed
     * @throws IOException if the recorded commit is not readable
     */
    Difference difference(T value, Recording.Commit commit) throws IOException {
        decode(commit, recorded);
        byte[] data;
        byte[] state = null;
        if (ros != null) {
            header.set(commit.timeNs(), frameId);
            ros.encode(header, value, cdr);
            data = Arrays.copyOf(cdr.buffer(), cdr.size());
            text.clear();
            json.encode(value, text);
            state = commit.state() == null ? null : Arrays.copyOf(text.array(), text.size());
        } else {
            text.clear();
            json.encode(value, text);
            data = Arrays.copyOf(text.array(), text.size());
        }
        decode(new Recording.Commit(commit.timeNs(), commit.generation(), data, state), replayed);
        try {
            int countA = fields.count(recorded);
            int countB = fields.count(replayed);
            if (countA != countB) {
                return new Difference("count", Integer.toString(countA), Integer.toString(countB));
            }
            for (Field f : fields.fields()) {
                Object a = f.get(recorded);
                Object b = f.get(replayed);
                if (f.getType().isArray()) {
                    int n = Math.min(Array.getLength(a), Array.getLength(b));
                    if (countA >= 0) {
                        n = Math.min(n, countA);
                    }
                    for (int i = 0; i < n; i++) {
                        Object x = Array.get(a, i);
                        Object y = Array.get(b, i);
                        if (!x.equals(y)) {
                            return new Difference(f.getName() + "[" + i + "]", x.toString(), y.toString());
                        }
                    }
                } else if (!a.equals(b)) {
                    return new Difference(f.getName(), a.toString(), b.toString());
                }
            }
        } catch (IllegalAccessException e) {
            throw new IllegalStateException("field of " + key.type().getName() + " not readable", e);
        }
        return new Difference("(encoding)", "-", "-");
    }

    /**
     * Where two values differ.
     *
     * @param field the field's name, with the index for an array element
     * @param recorded the recorded value
     * @param replayed the replayed value
     */
    record Difference(String field, String recorded, String replayed) {
    }
}
