package io.rtaware.replay;

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
import java.util.List;

/**
 * One key's values in and out of a recording, as the recorder encodes them: a ROS 2-typed key
 * as CDR plus its {@code /rtaware/state/<key>} JSON, any other key as JSON. Decodes a recorded
 * commit into a value, tells whether a value encodes to the same bytes as a recorded commit, and
 * names the first field in which two values differ. Not thread-safe.
 *
 * @param <T> the value type
 */
final class ValueCodec<T extends StateValue<T>> {

    private final Key<T> key;
    private final Ros2Codec<T> ros;
    private final JsonStateCodec json;
    private final StateFields fields;
    private final CdrReader reader = new CdrReader();
    private final CdrWriter cdr;
    private final ByteBuf text = new ByteBuf(1 << 14);
    private final Ros2Header header = new Ros2Header();
    private final T recorded;
    private final T replayed;

    @SuppressWarnings("unchecked")
    ValueCodec(Key<T> key) {
        this.key = key;
        this.ros = (Ros2Codec<T>) RosCodecs.forType(key.type());
        this.json = new JsonStateCodec(key.type(), ros != null);
        this.fields = StateFields.of(key.type());
        this.recorded = key.newBuffer();
        // Room for the largest message of this key: its fields plus the ROS 2 message's headers.
        this.cdr = ros == null ? null : new CdrWriter((int) Math.min(Integer.MAX_VALUE - 8,
                2 * fields.estimateBytes(recorded) + (64 << 10)));
        this.replayed = key.newBuffer();
    }

    /** @return the key */
    Key<T> key() {
        return key;
    }

    /**
     * Sets {@code into} to a recorded commit's value. Allocates nothing.
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
                    json.decode(commit.state(), 0, commit.state().length, into);
                }
            } else {
                json.decode(commit.data(), 0, commit.data().length, into);
            }
        } catch (CdrException | IllegalArgumentException e) {
            throw new IOException("recorded value of '" + key.name() + "' (generation " + commit.generation()
                    + ") is not readable: " + e.getMessage());
        }
    }

    /**
     * Tells whether a value is what a recorded commit holds, as far as the recording carries it:
     * a ROS 2-typed value must encode to the same CDR bytes (with the recorded header: its stamp
     * is when the data was measured or committed, which the value does not say) and equal the
     * recorded state fields; any other value must equal every recorded field. Doubles are equal
     * when their bits are. Allocates nothing.
     *
     * @param value a value
     * @param commit a recorded commit
     * @return true if they are the same
     * @throws IOException if the recorded commit is not readable
     */
    boolean sameAs(T value, Recording.Commit commit) throws IOException {
        decode(commit, recorded); // of a ROS 2-typed value, the header comes with it, as recorded
        if (ros != null) {
            ros.encode(header, value, cdr);
            if (!Arrays.equals(cdr.buffer(), 0, cdr.size(), commit.data(), 0, commit.data().length)) {
                return false;
            }
            if (commit.state() == null) {
                return true;
            }
        }
        // The CDR bytes matched; of a ROS 2-typed value, compare the scalars the state carries exactly
        // (its arrays came back through the ROS type, which may round them, e.g. yaw as a quaternion).
        return firstDifferentField(recorded, value, ros != null) == null;
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
        decode(commit, recorded); // of a ROS 2-typed value, the header comes with it, as recorded
        byte[] data;
        byte[] state = null;
        if (ros != null) {
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
        Difference d = firstDifferentField(recorded, replayed, false);
        if (d != null) {
            return d;
        }
        return new Difference("(encoding)", "-", "-");
    }

    /**
     * @param scalarsOnly true to compare the non-array fields only
     * @return the first field in which the two values differ (arrays up to their count), or null;
     *     allocates only to describe a difference
     */
    private Difference firstDifferentField(T a, T b, boolean scalarsOnly) {
        int countA = fields.count(a);
        int countB = fields.count(b);
        if (!scalarsOnly && countA != countB) {
            return new Difference("count", Integer.toString(countA), Integer.toString(countB));
        }
        try {
            List<Field> all = fields.fields();
            for (int k = 0; k < all.size(); k++) { // indexed: an iterator would allocate on every compare
                Field f = all.get(k);
                Class<?> t = f.getType();
                if (t.isArray() && scalarsOnly) {
                    continue;
                }
                if (t.isArray()) {
                    Object x = f.get(a);
                    Object y = f.get(b);
                    int n = Math.min(Array.getLength(x), Array.getLength(y));
                    if (countA >= 0) {
                        n = Math.min(n, countA);
                    }
                    int i = firstDifferentElement(x, y, t.getComponentType(), n);
                    if (i >= 0) {
                        return new Difference(f.getName() + "[" + i + "]", String.valueOf(Array.get(x, i)),
                                String.valueOf(Array.get(y, i)));
                    }
                } else if (t == double.class || t == float.class) {
                    if (Double.doubleToLongBits(f.getDouble(a)) != Double.doubleToLongBits(f.getDouble(b))) {
                        return new Difference(f.getName(), Double.toString(f.getDouble(a)), Double.toString(f.getDouble(b)));
                    }
                } else if (t == boolean.class) {
                    if (f.getBoolean(a) != f.getBoolean(b)) {
                        return new Difference(f.getName(), Boolean.toString(f.getBoolean(a)), Boolean.toString(f.getBoolean(b)));
                    }
                } else if (f.getLong(a) != f.getLong(b)) {
                    return new Difference(f.getName(), Long.toString(f.getLong(a)), Long.toString(f.getLong(b)));
                }
            }
        } catch (IllegalAccessException e) {
            throw new IllegalStateException("field of " + key.type().getName() + " not readable", e);
        }
        return null;
    }

    private static int firstDifferentElement(Object x, Object y, Class<?> c, int n) {
        for (int i = 0; i < n; i++) {
            boolean same;
            if (c == double.class) {
                same = Double.doubleToLongBits(((double[]) x)[i]) == Double.doubleToLongBits(((double[]) y)[i]);
            } else if (c == float.class) {
                same = Float.floatToIntBits(((float[]) x)[i]) == Float.floatToIntBits(((float[]) y)[i]);
            } else if (c == long.class) {
                same = ((long[]) x)[i] == ((long[]) y)[i];
            } else if (c == int.class) {
                same = ((int[]) x)[i] == ((int[]) y)[i];
            } else if (c == short.class) {
                same = ((short[]) x)[i] == ((short[]) y)[i];
            } else if (c == byte.class) {
                same = ((byte[]) x)[i] == ((byte[]) y)[i];
            } else if (c == boolean.class) {
                same = ((boolean[]) x)[i] == ((boolean[]) y)[i];
            } else {
                same = ((char[]) x)[i] == ((char[]) y)[i];
            }
            if (!same) {
                return i;
            }
        }
        return -1;
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
