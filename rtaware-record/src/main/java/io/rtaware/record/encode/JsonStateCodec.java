package io.rtaware.record.encode;

import com.fasterxml.jackson.core.io.NumberOutput;
import com.fasterxml.jackson.databind.JsonNode;
import java.lang.reflect.Array;
import java.lang.reflect.Field;

/**
 * A data-store value as JSON of its {@link StateFields} ({@code {"vxMps":0.25,"active":true}}),
 * with the JSON Schema MCAP's {@code jsonschema} encoding carries, and back (replay). Integers
 * and booleans are written without allocating; floating-point numbers go through
 * {@link Double#toString} (shortest representation that reads back to the same value), which
 * allocates a short string on the writer thread. Non-finite numbers are written as the strings
 * {@code "NaN"}, {@code "Infinity"}, {@code "-Infinity"}. Not thread-safe.
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
     * Sets the carried fields of {@code into} from an object this codec wrote (replay).
     *
     * @param node the JSON object
     * @param into receives the values
     * @throws IllegalArgumentException if a field is missing or an array exceeds its capacity
     */
    public void decode(JsonNode node, Object into) {
        try {
            for (Field f : fields.fields()) {
                if (!carried(f)) {
                    continue;
                }
                JsonNode v = node.get(f.getName());
                if (v == null) {
                    throw new IllegalArgumentException("recorded " + fields.type().getSimpleName() + " lacks field " + f.getName());
                }
                Class<?> t = f.getType();
                if (t.isArray()) {
                    Object array = f.get(into);
                    if (v.size() > Array.getLength(array)) {
                        throw new IllegalArgumentException("recorded " + f.getName() + " of " + v.size()
                                + " elements exceeds the capacity of " + Array.getLength(array));
                    }
                    for (int k = 0; k < v.size(); k++) {
                        setElement(array, t.getComponentType(), k, v.get(k));
                    }
                } else if (t == double.class) {
                    f.setDouble(into, doubleOf(v));
                } else if (t == float.class) {
                    f.setFloat(into, (float) doubleOf(v));
                } else if (t == boolean.class) {
                    f.setBoolean(into, v.asBoolean());
                } else if (t == long.class) {
                    f.setLong(into, v.asLong());
                } else if (t == int.class) {
                    f.setInt(into, v.asInt());
                } else if (t == short.class) {
                    f.setShort(into, (short) v.asInt());
                } else if (t == byte.class) {
                    f.setByte(into, (byte) v.asInt());
                } else {
                    f.setChar(into, (char) v.asInt());
                }
            }
            JsonNode count = node.get("count");
            if (count != null && !scalarsOnly) {
                fields.setCount(into, count.asInt());
            }
        } catch (IllegalAccessException e) {
            throw new IllegalStateException("field of " + fields.type().getName() + " not settable", e);
        }
    }

    private static double doubleOf(JsonNode v) {
        return v.isTextual() ? Double.parseDouble(v.asText()) : v.asDouble();
    }

    private static void setElement(Object array, Class<?> component, int k, JsonNode v) {
        if (component == double.class) {
            ((double[]) array)[k] = doubleOf(v);
        } else if (component == float.class) {
            ((float[]) array)[k] = (float) doubleOf(v);
        } else if (component == long.class) {
            ((long[]) array)[k] = v.asLong();
        } else if (component == int.class) {
            ((int[]) array)[k] = v.asInt();
        } else if (component == short.class) {
            ((short[]) array)[k] = (short) v.asInt();
        } else if (component == byte.class) {
            ((byte[]) array)[k] = (byte) v.asInt();
        } else if (component == boolean.class) {
            ((boolean[]) array)[k] = v.asBoolean();
        } else {
            ((char[]) array)[k] = (char) v.asInt();
        }
    }
}
