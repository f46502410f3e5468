package io.rtaware.app.foxglove;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.Iterator;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Checks a Foxglove (or Lichtblick) layout against the channels a recording advertises: every
 * topic a panel names is a channel, and every message path a panel reads (Foxglove's syntax:
 * {@code /topic.field[:]{other==1}.leaf}, a quoted topic {@code "/a.b".field}) names fields of
 * that channel's {@code ros2msg} schema, array elements only through an index or a slice, and
 * ends on a value where the panel plots or tracks one; a 3D panel's display frame
 * ({@code followTf}) is a frame of the recording and every topic it shows is in that frame or in
 * one below it on the recording's transforms (else Foxglove cannot place it). The panels read are those the shipped
 * layout uses ({@code 3D}, {@code Plot}, {@code StateTransitions}, {@code RosOut}, {@code Table});
 * any other panel type is a problem, so a panel added to the layout is never left unchecked.
 * Field names and config keys as Lichtblick's sources define them (2025-03).
 */
public final class FoxgloveLayoutCheck {

    /** The message types Foxglove's Log panel reads. */
    public static final Set<String> LOG_TYPES = Set.of("rcl_interfaces/msg/Log", "rosgraph_msgs/Log", "foxglove_msgs/msg/Log",
            "foxglove.Log");
    private static final Set<String> PRIMITIVES = Set.of("bool", "byte", "char", "float32", "float64", "int8", "uint8",
            "int16", "uint16", "int32", "uint32", "int64", "uint64", "string", "wstring");
    private static final Set<String> NUMERIC = Set.of("bool", "byte", "char", "float32", "float64", "int8", "uint8",
            "int16", "uint16", "int32", "uint32", "int64", "uint64");

    /** One field of a message type. */
    private record Field(String name, String type, boolean array) {
    }

    /**
     * A channel as a recording or a live server advertises it.
     *
     * @param schemaName its schema's name, e.g. {@code rtaware_msgs/msg/TaskCycle}
     * @param schemaText its {@code ros2msg} schema, the type's definition and its dependencies'
     * @param frameId its messages' header frame (the channel's {@code frame_id} metadata), or null
     */
    public record Channel(String schemaName, String schemaText, String frameId) {
    }

    private final Map<String, Channel> channels;
    /** Each frame's parent on the recording's {@code /tf} and {@code /tf_static}. */
    private final Map<String, String> parentOf;
    private final List<String> problems = new ArrayList<>();
    private final Set<String> topicsRead = new LinkedHashSet<>();

    private FoxgloveLayoutCheck(Map<String, Channel> channels, Map<String, String> parentOf) {
        this.channels = channels;
        this.parentOf = parentOf;
    }

    /**
     * @param layout the layout's JSON (as Foxglove's "Export layout" writes it)
     * @param channels the recording's channels by topic
     * @param parentOf each frame's parent on the recording's transforms
     * @return every problem found, one line each; empty if the layout reads only what the recording holds
     */
    public static List<String> problems(JsonNode layout, Map<String, Channel> channels, Map<String, String> parentOf) {
        FoxgloveLayoutCheck check = new FoxgloveLayoutCheck(channels, parentOf);
        check.layout(layout);
        return check.problems;
    }

    /**
     * @param layout a layout
     * @param channels the recording's channels by topic
     * @return the topics its panels read
     */
    public static Set<String> topics(JsonNode layout, Map<String, Channel> channels) {
        FoxgloveLayoutCheck check = new FoxgloveLayoutCheck(channels, Map.of());
        check.layout(layout);
        return check.topicsRead;
    }

    /**
     * @return the layout shipped in the repository ({@code docs/foxglove/rtaware-layout.json})
     * @throws java.io.IOException if it cannot be read
     */
    public static JsonNode shipped() throws java.io.IOException {
        return new com.fasterxml.jackson.databind.ObjectMapper()
                .readTree(java.nio.file.Path.of("..", "docs", "foxglove", "rtaware-layout.json").toFile());
    }

    private void layout(JsonNode layout) {
        JsonNode configs = layout.path("configById");
        Set<String> placed = new LinkedHashSet<>();
        tree(layout.path("layout"), placed);
        for (Iterator<String> ids = configs.fieldNames(); ids.hasNext(); ) {
            String id = ids.next();
            if (!placed.contains(id)) {
                problems.add(id + ": configured but not placed in the layout");
            }
        }
        for (String id : placed) {
            if (!configs.has(id)) {
                problems.add(id + ": placed in the layout but not configured");
                continue;
            }
            panel(id, configs.get(id));
        }
    }

    private void tree(JsonNode node, Set<String> placed) {
        if (node.isTextual()) {
            placed.add(node.asText());
        } else if (node.isObject()) {
            tree(node.path("first"), placed);
            tree(node.path("second"), placed);
        } else {
            problems.add("layout: not a panel id or a split: " + node);
        }
    }

    private void panel(String id, JsonNode config) {
        String type = id.substring(0, Math.max(0, id.indexOf('!')));
        switch (type) {
            case "3D" -> {
                String display = config.path("followTf").asText();
                if (!parentOf.isEmpty() && !parentOf.containsKey(display) && !parentOf.containsValue(display)) {
                    problems.add(id + ": display frame '" + display + "' is no frame of the recording's transforms");
                }
                config.path("topics").fieldNames().forEachRemaining(topic -> {
                    if (topic(id, topic)) {
                        placed(id, topic, display);
                    }
                });
            }
            case "Plot" -> {
                for (JsonNode path : config.path("paths")) {
                    String value = path.path("value").asText();
                    if (!isNumber(value)) { // a number is a reference line
                        path(id, value, NUMERIC);
                    }
                }
                if (config.has("xAxisPath")) {
                    path(id, config.path("xAxisPath").path("value").asText(), NUMERIC);
                }
            }
            case "StateTransitions" -> config.path("paths").forEach(p -> path(id, p.path("value").asText(), PRIMITIVES));
            case "RosOut" -> {
                String topic = config.path("topicToRender").asText();
                if (topic(id, topic) && !LOG_TYPES.contains(channels.get(topic).schemaName())) {
                    problems.add(id + ": " + topic + " is " + channels.get(topic).schemaName()
                            + ", not a type the Log panel reads " + LOG_TYPES);
                }
            }
            case "Table" -> path(id, config.path("topicPath").asText(), null);
            default -> problems.add(id + ": panel type '" + type + "' is not checked by this test");
        }
    }

    /** A 3D panel can place a topic whose frame is its display frame or below it on the transforms. */
    private void placed(String panel, String topic, String display) {
        String frame = channels.get(topic).frameId();
        if (frame == null || parentOf.isEmpty()) {
            return;
        }
        for (String f = frame; f != null; f = parentOf.get(f)) {
            if (f.equals(display)) {
                return;
            }
        }
        problems.add(panel + ": " + topic + " is in frame '" + frame + "', which no transform places in the display frame '"
                + display + "'");
    }

    private static boolean isNumber(String s) {
        try {
            Double.parseDouble(s);
            return true;
        } catch (NumberFormatException e) {
            return false;
        }
    }

    /** @return true if the recording advertises the topic */
    private boolean topic(String panel, String topic) {
        topicsRead.add(topic);
        if (!channels.containsKey(topic)) {
            problems.add(panel + ": topic " + topic + " is not advertised by the recording");
            return false;
        }
        return true;
    }

    /**
     * Follows a message path through the channel's schema.
     *
     * @param leaves the types the path must end on, or null for any (a whole message too)
     */
    private void path(String panel, String path, Set<String> leaves) {
        int i;
        String topic;
        if (path.startsWith("\"")) {
            i = path.indexOf('"', 1);
            if (i < 0) {
                problems.add(panel + ": unclosed quoted topic in " + path);
                return;
            }
            topic = path.substring(1, i);
            i++;
        } else {
            i = 0;
            while (i < path.length() && (Character.isLetterOrDigit(path.charAt(i)) || "/_-".indexOf(path.charAt(i)) >= 0)) {
                i++;
            }
            topic = path.substring(0, i);
        }
        if (!topic(panel, topic)) {
            return;
        }
        Map<String, List<Field>> types = types(channels.get(topic));
        String type = channels.get(topic).schemaName();
        boolean array = false;
        while (i < path.length()) {
            char c = path.charAt(i);
            if (c == '.' && i + 1 < path.length() && path.charAt(i + 1) == '@') {
                break; // a modifier (.@derivative ...) applies to the value reached
            } else if (c == '.') {
                int end = i + 1;
                while (end < path.length() && (Character.isLetterOrDigit(path.charAt(end)) || path.charAt(end) == '_')) {
                    end++;
                }
                String name = path.substring(i + 1, end);
                if (array) {
                    problems.add(panel + ": " + path + ": field " + name + " of an array without an index or slice");
                    return;
                }
                Field f = field(types, type, name);
                if (f == null) {
                    problems.add(panel + ": " + path + ": no field '" + name + "' in " + type);
                    return;
                }
                type = f.type();
                array = f.array();
                i = end;
            } else if (c == '[') {
                int end = path.indexOf(']', i);
                if (!array || end < 0) {
                    problems.add(panel + ": " + path + ": an index or slice of what is not an array");
                    return;
                }
                array = false;
                i = end + 1;
            } else if (c == '{') {
                int end = path.indexOf('}', i);
                String filter = end < 0 ? "" : path.substring(i + 1, end);
                int op = filter.indexOf("==") >= 0 ? filter.indexOf("==") : filter.indexOf("!=");
                String name = op < 0 ? "" : filter.substring(0, op).strip();
                String filtered = type;
                for (String part : name.split("\\.")) {
                    Field f = array ? null : field(types, filtered, part);
                    if (f == null) {
                        problems.add(panel + ": " + path + ": the filter {" + filter + "} names no field of " + type);
                        return;
                    }
                    filtered = f.type();
                }
                i = end + 1;
            } else {
                problems.add(panel + ": " + path + ": cannot read '" + path.substring(i) + "'");
                return;
            }
        }
        if (leaves != null && (array || !leaves.contains(type))) {
            problems.add(panel + ": " + path + " ends on " + type + (array ? "[]" : "") + ", not a value this panel draws");
        }
    }

    private static Field field(Map<String, List<Field>> types, String type, String name) {
        List<Field> fields = types.get(normalized(type));
        if (fields == null) {
            return null;
        }
        return fields.stream().filter(f -> f.name().equals(name)).findFirst().orElse(null);
    }

    /** {@code pkg/msg/Type} and {@code pkg/Type} are one name. */
    private static String normalized(String type) {
        return type.replace("/msg/", "/");
    }

    /** The types of a ros2msg schema: the channel's own, then each {@code MSG:} section. */
    private static Map<String, List<Field>> types(Channel channel) {
        Map<String, List<Field>> types = new HashMap<>();
        String current = normalized(channel.schemaName());
        List<Field> fields = new ArrayList<>();
        types.put(current, fields);
        for (String raw : channel.schemaText().split("\n")) {
            String line = raw.strip();
            if (line.matches("={3,}")) {
                continue;
            }
            if (line.startsWith("MSG:")) {
                current = normalized(line.substring(4).strip());
                fields = new ArrayList<>();
                types.put(current, fields);
                continue;
            }
            int hash = line.indexOf('#');
            line = (hash >= 0 ? line.substring(0, hash) : line).strip();
            String[] parts = line.split("\\s+");
            if (parts.length < 2 || parts[1].contains("=")) {
                continue; // blank, comment or constant
            }
            String type = parts[0];
            boolean array = type.contains("[");
            if (array) {
                type = type.substring(0, type.indexOf('['));
            }
            if (type.contains("<=")) {
                type = type.substring(0, type.indexOf("<=")); // a bounded string
            }
            if (!PRIMITIVES.contains(type) && !type.contains("/")) {
                type = current.substring(0, current.indexOf('/') + 1) + type; // same package
            }
            fields.add(new Field(parts[1], PRIMITIVES.contains(type) ? type : normalized(type), array));
        }
        return types;
    }
}
