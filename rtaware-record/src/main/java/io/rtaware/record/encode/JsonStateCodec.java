package io.rtaware.record.encode;

import com.fasterxml.jackson.core.io.NumberOutput;
import java.lang.reflect.Array;
import java.lang.reflect.Field;

/**
 * A data-store value as JSON of its {@link StateFields} ({@code {"vxMps":0.25,"active":true}}),
 * with the JSON Schema MCAP's {@code jsonschema} encoding carries, and back (replay). Integers
 * and booleans are written without allocating; floating-point numbers go through
 * {@link Double#toString} (shortest representation that reads back to the same value), which
 * allocates a short string on the writer thread. Non-finite numbers are written as the strings
 * {@code "NaN"}, {@code "Infinity"}, {@code "-Infinity"}. Reading back (replay) allocates nothing.
 * Not thread-safe.
 */
public final class JsonStateCodec {

    private final StateFields fields;
    private final boolean scalarsOnly;
    private final byte[][] names;

    /**
     * @param type the value class
     * @param scalarsOnly true to carry only the non-array fields (the part a ROS 2 message lacks)
     */
    public JsonStateCodec(Class<?> type, boolean scalarsOnly) {
        this.fields = StateFields.of(type);
        this.scalarsOnly = scalarsOnly;
        this.names = new byte[fields.fields().size()][];
        this.seen = new boolean[names.length];
        for (int i = 0; i < names.length; i++) {
            names[i] = ("\"" + fields.fields().get(i).getName() + "\":").getBytes(java.nio.charset.StandardCharsets.US_ASCII);
        }
    }

    private boolean carried(Field f) {
        return !scalarsOnly || !f.getType().isArray();
    }

    /** @return the JSON Schema (draft 2020-12) of the encoded objects */
    public String jsonSchema() {
        StringBuilder sb = new StringBuilder("{\"$schema\":\"https://json-schema.org/draft/2020-12/schema\",")
                .append("\"title\":\"").append(fields.type().getName()).append("\",\"type\":\"object\",\"properties\":{");
        boolean first = true;
        for (Field f : fields.fields()) {
            if (!carried(f)) {
                continue;
            }
            sb.append(first ? "" : ",").append('"').append(f.getName()).append("\":");
            first = false;
            if (f.getType().isArray()) {
                sb.append("{\"type\":\"array\",\"items\":{\"type\":\"").append(jsonType(f.getType().getComponentType()))
                        .append("\"}}");
            } else {
                sb.append("{\"type\":\"").append(jsonType(f.getType())).append("\"}");
            }
        }
        if (fields.counted() && !scalarsOnly) {
            sb.append(first ? "" : ",").append("\"count\":{\"type\":\"integer\"}");
        }
        return sb.append("}}").toString();
    }

    private static String jsonType(Class<?> t) {
        if (t == boolean.class) {
            return "boolean";
        }
        return t == double.class || t == float.class ? "number" : "integer";
    }

    /**
     * Writes the value as one JSON object.
     *
     * @param value an instance of the class
     * @param out receives the bytes (appended)
     */
    public void encode(Object value, ByteBuf out) {
        try {
            out.put('{');
            boolean first = true;
            int count = scalarsOnly ? -1 : fields.count(value);
            for (int i = 0; i < names.length; i++) {
                Field f = fields.fields().get(i);
                if (!carried(f)) {
                    continue;
                }
                if (!first) {
                    out.put(',');
                }
                first = false;
                out.put(names[i], 0, names[i].length);
                Class<?> t = f.getType();
                if (t.isArray()) {
                    Object array = f.get(value);
                    int n = count >= 0 ? Math.min(count, Array.getLength(array)) : Array.getLength(array);
                    out.put('[');
                    for (int k = 0; k < n; k++) {
                        if (k > 0) {
                            out.put(',');
                        }
                        element(array, t.getComponentType(), k, out);
                    }
                    out.put(']');
                } else if (t == double.class) {
                    number(f.getDouble(value), out);
                } else if (t == float.class) {
                    number(f.getFloat(value), out);
                } else if (t == boolean.class) {
                    out.putAscii(f.getBoolean(value) ? "true" : "false");
                } else {
                    integer(f.getLong(value), out);
                }
            }
            if (count >= 0) {
                out.putAscii(first ? "\"count\":" : ",\"count\":");
                integer(count, out);
            }
            out.put('}');
        } catch (IllegalAccessException e) {
            throw new IllegalStateException("field of " + fields.type().getName() + " not readable", e);
        }
    }

    private static void element(Object array, Class<?> component, int k, ByteBuf out) {
        if (component == double.class) {
            number(((double[]) array)[k], out);
        } else if (component == float.class) {
            number(((float[]) array)[k], out);
        } else if (component == long.class) {
            integer(((long[]) array)[k], out);
        } else if (component == int.class) {
            integer(((int[]) array)[k], out);
        } else if (component == short.class) {
            integer(((short[]) array)[k], out);
        } else if (component == byte.class) {
            integer(((byte[]) array)[k], out);
        } else if (component == boolean.class) {
            out.putAscii(((boolean[]) array)[k] ? "true" : "false");
        } else {
            integer(((char[]) array)[k], out);
        }
    }

    private static void integer(long v, ByteBuf out) {
        out.ensure(24);
        out.size(NumberOutput.outputLong(v, out.array(), out.size()));
    }

    private static void number(double v, ByteBuf out) {
        if (Double.isFinite(v)) {
            out.putAscii(Double.toString(v));
        } else {
            out.putAscii(Double.isNaN(v) ? "\"NaN\"" : v > 0 ? "\"Infinity\"" : "\"-Infinity\"");
        }
    }

    private static void number(float v, ByteBuf out) {
        if (Float.isFinite(v)) {
            out.putAscii(Float.toString(v));
        } else {
            out.putAscii(Float.isNaN(v) ? "\"NaN\"" : v > 0 ? "\"Infinity\"" : "\"-Infinity\"");
        }
    }

    /**
     * Sets the carried fields of {@code into} from an object this codec wrote (replay), without
     * allocating: the bytes are scanned in place and numbers parsed by FastDoubleParser.
     *
     * @param json buffer holding the object
     * @param offset its first byte
     * @param length its length
     * @param into receives the values
     * @throws IllegalArgumentException if the object is malformed, lacks a field, or an array
     *     exceeds its capacity
     */
    public void decode(byte[] json, int offset, int length, Object into) {
        Scanner in = scanner.reset(json, offset, offset + length);
        java.util.Arrays.fill(seen, false);
        try {
            in.expect('{');
            boolean countSeen = false;
            if (in.peek() != '}') {
                do {
                    int field = in.fieldName();
                    if (field == COUNT) {
                        int count = (int) in.integer();
                        if (!scalarsOnly) {
                            fields.setCount(into, count);
                        }
                        countSeen = true;
                    } else {
                        Field f = fields.fields().get(field);
                        seen[field] = true;
                        value(in, f, into);
                    }
                } while (in.comma());
            }
            in.expect('}');
            for (int i = 0; i < names.length; i++) {
                if (!seen[i] && carried(fields.fields().get(i))) {
                    throw new IllegalArgumentException("recorded " + fields.type().getSimpleName() + " lacks field "
                            + fields.fields().get(i).getName());
                }
            }
            if (!scalarsOnly && fields.counted() && !countSeen) {
                throw new IllegalArgumentException("recorded " + fields.type().getSimpleName() + " lacks its count");
            }
        } catch (IllegalAccessException e) {
            throw new IllegalStateException("field of " + fields.type().getName() + " not settable", e);
        }
    }

    private void value(Scanner in, Field f, Object into) throws IllegalAccessException {
        Class<?> t = f.getType();
        if (t.isArray()) {
            Object array = f.get(into);
            Class<?> c = t.getComponentType();
            int capacity = Array.getLength(array);
            in.expect('[');
            int k = 0;
            if (in.peek() != ']') {
                do {
                    if (k == capacity) {
                        throw new IllegalArgumentException("recorded " + f.getName() + " exceeds the capacity of "
                                + capacity + " elements");
                    }
                    if (c == double.class) {
                        ((double[]) array)[k] = in.number();
                    } else if (c == float.class) {
                        ((float[]) array)[k] = (float) in.number();
                    } else if (c == boolean.class) {
                        ((boolean[]) array)[k] = in.bool();
                    } else if (c == long.class) {
                        ((long[]) array)[k] = in.integer();
                    } else if (c == int.class) {
                        ((int[]) array)[k] = (int) in.integer();
                    } else if (c == short.class) {
                        ((short[]) array)[k] = (short) in.integer();
                    } else if (c == byte.class) {
                        ((byte[]) array)[k] = (byte) in.integer();
                    } else {
                        ((char[]) array)[k] = (char) in.integer();
                    }
                    k++;
                } while (in.comma());
            }
            in.expect(']');
        } else if (t == double.class) {
            f.setDouble(into, in.number());
        } else if (t == float.class) {
            f.setFloat(into, (float) in.number());
        } else if (t == boolean.class) {
            f.setBoolean(into, in.bool());
        } else if (t == long.class) {
            f.setLong(into, in.integer());
        } else if (t == int.class) {
            f.setInt(into, (int) in.integer());
        } else if (t == short.class) {
            f.setShort(into, (short) in.integer());
        } else if (t == byte.class) {
            f.setByte(into, (byte) in.integer());
        } else {
            f.setChar(into, (char) in.integer());
        }
    }

    /** Field index of {@code "count"} in {@link Scanner#fieldName()}. */
    private static final int COUNT = -1;
    private final boolean[] seen;
    private final Scanner scanner = new Scanner();

    /** An allocation-free reader of the flat JSON objects this codec writes. */
    private final class Scanner {
        private byte[] b;
        private int at;
        private int end;

        Scanner reset(byte[] bytes, int from, int to) {
            b = bytes;
            at = from;
            end = to;
            return this;
        }

        private void skipSpace() {
            while (at < end && (b[at] == ' ' || b[at] == '\n' || b[at] == '\r' || b[at] == '\t')) {
                at++;
            }
        }

        int peek() {
            skipSpace();
            if (at >= end) {
                throw malformed("ends early");
            }
            return b[at];
        }

        void expect(char c) {
            if (peek() != c) {
                throw malformed("expected '" + c + "'");
            }
            at++;
        }

        boolean comma() {
            if (peek() == ',') {
                at++;
                return true;
            }
            return false;
        }

        /** Reads {@code "name":} and returns the field's index, or {@link #COUNT}. */
        int fieldName() {
            if (peek() != '"') {
                throw malformed("expected a field name");
            }
            int start = at;
            int close = at + 1;
            while (close < end && b[close] != '"') {
                close++;
            }
            int nameEnd = close + 1;
            at = nameEnd;
            expect(':');
            int length = nameEnd - start;
            for (int i = 0; i < names.length; i++) {
                byte[] n = names[i];
                // names[i] is "\"name\":"; compare the quoted name without the colon
                if (n.length - 1 == length && java.util.Arrays.equals(n, 0, length, b, start, nameEnd)) {
                    return i;
                }
            }
            if (length == 7 && java.util.Arrays.equals(COUNT_NAME, 0, 7, b, start, nameEnd)) {
                return COUNT;
            }
            throw malformed("unknown field " + new String(b, start, length, java.nio.charset.StandardCharsets.UTF_8));
        }

        double number() {
            skipSpace();
            if (at < end && b[at] == '"') {
                int close = at + 1;
                while (close < end && b[close] != '"') {
                    close++;
                }
                double v = parse(at + 1, close);
                at = close + 1;
                return v;
            }
            int start = at;
            while (at < end && isNumberByte(b[at])) {
                at++;
            }
            return parse(start, at);
        }

        private double parse(int from, int to) {
            try {
                return ch.randelshofer.fastdoubleparser.JavaDoubleParser.parseDouble(b, from, to - from);
            } catch (NumberFormatException e) {
                throw malformed("not a number");
            }
        }

        long integer() {
            skipSpace();
            int start = at;
            boolean negative = at < end && b[at] == '-';
            if (negative) {
                at++;
            }
            long v = 0;
            int digits = 0;
            while (at < end && b[at] >= '0' && b[at] <= '9') {
                v = v * 10 + (b[at++] - '0');
                digits++;
            }
            if (digits == 0 || digits > 19) {
                at = start;
                throw malformed("not an integer");
            }
            return negative ? -v : v;
        }

        boolean bool() {
            skipSpace();
            if (end - at >= 4 && b[at] == 't' && b[at + 1] == 'r' && b[at + 2] == 'u' && b[at + 3] == 'e') {
                at += 4;
                return true;
            }
            if (end - at >= 5 && b[at] == 'f' && b[at + 1] == 'a' && b[at + 2] == 'l' && b[at + 3] == 's'
                    && b[at + 4] == 'e') {
                at += 5;
                return false;
            }
            throw malformed("not a boolean");
        }

        private IllegalArgumentException malformed(String what) {
            return new IllegalArgumentException("recorded " + fields.type().getSimpleName() + " JSON is malformed: "
                    + what + " at byte " + at);
        }
    }

    private static boolean isNumberByte(byte c) {
        return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
    }

    private static final byte[] COUNT_NAME = "\"count\"".getBytes(java.nio.charset.StandardCharsets.US_ASCII);
}
