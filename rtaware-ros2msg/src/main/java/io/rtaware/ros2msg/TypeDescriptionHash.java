package io.rtaware.ros2msg;

import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;

/**
 * The RIHS01 type hash of a message type as ROS 2 computes it (REP 2011, type description
 * version 1; {@code rosidl_generator_type_description}): SHA-256 over the JSON of the type's
 * description, its fields with their type ids, capacities and nested type names (constants and
 * default values left out), followed by the descriptions of every type it refers to, directly
 * or not, in order of their names. The JSON is written in the exact form of Python's
 * {@code json.dumps} with its default separators ({@code ", "} and {@code ": "}), which the hash
 * is defined over; every name in it is a ROS 2 identifier, so nothing needs escaping.
 *
 * <p>Reads {@code .msg} definitions of primitive types ({@code bool}, {@code byte}, the integer
 * and floating-point types), {@code string} and {@code string<=N}, nested types, and arrays
 * {@code T[N]}, bounded {@code T[<=N]} and unbounded {@code T[]} sequences of any of those;
 * comments, constants and default values are skipped. Stateless.
 */
public final class TypeDescriptionHash {

    /** The prefix of a version 1 hash. */
    public static final String PREFIX = "RIHS01_";

    private static final int NESTED = 1;
    private static final int BOUNDED_STRING = 21;
    private static final int ARRAY = 48;
    private static final int BOUNDED_SEQUENCE = 96;
    private static final int UNBOUNDED_SEQUENCE = 144;
    /** rosidl's field type ids of the primitive types (type_description_interfaces/msg/FieldType). */
    private static final Map<String, Integer> PRIMITIVE_IDS = Map.ofEntries(
            Map.entry("int8", 2), Map.entry("uint8", 3), Map.entry("int16", 4), Map.entry("uint16", 5),
            Map.entry("int32", 6), Map.entry("uint32", 7), Map.entry("int64", 8), Map.entry("uint64", 9),
            Map.entry("float32", 10), Map.entry("float64", 11), Map.entry("bool", 15), Map.entry("byte", 16),
            Map.entry("string", 17));

    private TypeDescriptionHash() {
    }

    /**
     * @param definition a message type with the definitions of every type its fields use
     * @return its RIHS01 hash, {@code RIHS01_} and 64 hex digits
     * @throws IllegalArgumentException if the definition uses a type this class does not read
     *     or names a nested type it was not given
     */
    public static String rihs01(MessageDefinition definition) {
        return PREFIX + HexFormat.of().formatHex(sha256(canonicalJson(definition)));
    }

    /**
     * @param definition a message type with the definitions of every type its fields use
     * @return the JSON the hash is computed over
     */
    static String canonicalJson(MessageDefinition definition) {
        Map<String, MessageDefinition> referenced = new TreeMap<>();
        collect(definition, referenced);
        referenced.remove(definition.name());
        StringBuilder json = new StringBuilder(1024);
        json.append("{\"type_description\": ");
        describe(definition, json);
        json.append(", \"referenced_type_descriptions\": [");
        boolean first = true;
        for (MessageDefinition d : referenced.values()) {
            if (!first) {
                json.append(", ");
            }
            first = false;
            describe(d, json);
        }
        return json.append("]}").toString();
    }

    private static void collect(MessageDefinition d, Map<String, MessageDefinition> into) {
        if (into.putIfAbsent(d.name(), d) != null) {
            return;
        }
        for (Field f : fields(d)) {
            if (f.nestedType() != null) {
                MessageDefinition nested = find(d, f.nestedType(), new HashSet<>());
                if (nested == null) {
                    throw new IllegalArgumentException(d.name() + " uses " + f.nestedType()
                            + ", whose definition was not given");
                }
                collect(nested, into);
            }
        }
    }

    /** Finds a type among a definition's dependencies, depth first. */
    private static MessageDefinition find(MessageDefinition d, String name, Set<String> seen) {
        if (d.name().equals(name)) {
            return d;
        }
        if (!seen.add(d.name())) {
            return null;
        }
        for (MessageDefinition dep : d.dependencies()) {
            MessageDefinition found = find(dep, name, seen);
            if (found != null) {
                return found;
            }
        }
        return null;
    }

    private static void describe(MessageDefinition d, StringBuilder json) {
        json.append("{\"type_name\": \"").append(d.name()).append("\", \"fields\": [");
        List<Field> fields = fields(d);
        if (fields.isEmpty()) {
            // rosidl gives an empty message one placeholder member
            fields = List.of(new Field("structure_needs_at_least_one_member", PRIMITIVE_IDS.get("uint8"), 0, 0, null));
        }
        for (int i = 0; i < fields.size(); i++) {
            Field f = fields.get(i);
            if (i > 0) {
                json.append(", ");
            }
            json.append("{\"name\": \"").append(f.name()).append("\", \"type\": {\"type_id\": ").append(f.typeId())
                    .append(", \"capacity\": ").append(f.capacity())
                    .append(", \"string_capacity\": ").append(f.stringCapacity())
                    .append(", \"nested_type_name\": \"").append(f.nestedType() == null ? "" : f.nestedType())
                    .append("\"}}");
        }
        json.append("]}");
    }

    /** One field of a type description; {@code nestedType} null for the primitive types. */
    private record Field(String name, int typeId, int capacity, int stringCapacity, String nestedType) {
    }

    /** The fields of a definition in their order: comments, constants and default values left out. */
    private static List<Field> fields(MessageDefinition d) {
        List<Field> fields = new ArrayList<>();
        String pkg = d.name().substring(0, d.name().indexOf('/'));
        for (String raw : d.text().split("\n", -1)) {
            int hash = raw.indexOf('#');
            String line = (hash >= 0 ? raw.substring(0, hash) : raw).strip();
            if (line.isEmpty()) {
                continue;
            }
            String[] parts = line.split("\\s+", 3);
            if (parts.length < 2) {
                throw new IllegalArgumentException(d.name() + ": not a field: '" + raw + "'");
            }
            String type = parts[0];
            String name = parts[1];
            int equals = name.indexOf('=');
            if (equals >= 0 || (parts.length == 3 && parts[2].startsWith("="))) {
                continue; // a constant: not part of the type description
            }
            fields.add(field(d, pkg, type, name));
        }
        return fields;
    }

    private static Field field(MessageDefinition d, String pkg, String type, String name) {
        int bracket = type.indexOf('[');
        int increment = 0;
        int capacity = 0;
        String element = type;
        if (bracket >= 0) {
            if (!type.endsWith("]")) {
                throw new IllegalArgumentException(d.name() + ": malformed array type '" + type + "'");
            }
            String size = type.substring(bracket + 1, type.length() - 1);
            element = type.substring(0, bracket);
            if (size.isEmpty()) {
                increment = UNBOUNDED_SEQUENCE;
            } else if (size.startsWith("<=")) {
                increment = BOUNDED_SEQUENCE;
                capacity = Integer.parseInt(size.substring(2));
            } else {
                increment = ARRAY;
                capacity = Integer.parseInt(size);
            }
        }
        if (element.startsWith("string<=")) {
            return new Field(name, increment + BOUNDED_STRING, capacity, Integer.parseInt(element.substring(8)), null);
        }
        Integer primitive = PRIMITIVE_IDS.get(element);
        if (primitive != null) {
            return new Field(name, increment + primitive, capacity, 0, null);
        }
        if (!element.matches("([A-Za-z][A-Za-z0-9_]*/)?[A-Z][A-Za-z0-9]*")) {
            throw new IllegalArgumentException(d.name() + ": field type '" + type + "' is not read (wide strings, "
                    + "char and the old time/duration aliases are not supported)");
        }
        int slash = element.indexOf('/');
        String nested = slash < 0 ? pkg + "/msg/" + element
                : element.substring(0, slash) + "/msg/" + element.substring(slash + 1);
        return new Field(name, increment + NESTED, capacity, 0, nested);
    }

    private static byte[] sha256(String text) {
        try {
            return MessageDigest.getInstance("SHA-256").digest(text.getBytes(StandardCharsets.US_ASCII));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-256 is part of every JDK", e);
        }
    }
}
