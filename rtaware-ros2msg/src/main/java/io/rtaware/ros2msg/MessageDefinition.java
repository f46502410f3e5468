package io.rtaware.ros2msg;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Objects;
import java.util.Set;

/**
 * The ROS 2 {@code .msg} definition of one type (without comments) and the types its fields
 * use. Immutable.
 */
public final class MessageDefinition {

    private static final String SEPARATOR = "=".repeat(80);

    private final String name;
    private final String text;
    private final List<MessageDefinition> dependencies;

    /**
     * @param name full name, e.g. {@code geometry_msgs/msg/Twist}
     * @param text the definition's lines, each ending with a newline
     * @param dependencies the message types of its fields, in field order
     */
    public MessageDefinition(String name, String text, MessageDefinition... dependencies) {
        this.name = Objects.requireNonNull(name);
        this.text = Objects.requireNonNull(text);
        this.dependencies = List.of(dependencies);
    }

    /** @return the full name, e.g. {@code geometry_msgs/msg/Twist} */
    public String name() {
        return name;
    }

    /** @return the name without {@code /msg/}, as field types and MCAP's {@code MSG:} lines spell it */
    public String shortName() {
        return name.replace("/msg/", "/");
    }

    /** @return the message types of its fields, in field order */
    public List<MessageDefinition> dependencies() {
        return dependencies;
    }

    /** @return this type's own definition text */
    public String text() {
        return text;
    }

    /**
     * The text MCAP's {@code ros2msg} schema encoding wants: this definition, then each type it
     * depends on (depth first, in field order, each once) after a line of 80 {@code =} and a
     * line {@code MSG: pkg/Type}.
     *
     * @return the concatenated definition
     */
    public String schemaText() {
        Set<MessageDefinition> seen = new LinkedHashSet<>();
        collect(this, seen);
        StringBuilder out = new StringBuilder(text);
        List<MessageDefinition> ordered = new ArrayList<>(seen);
        for (MessageDefinition d : ordered.subList(1, ordered.size())) {
            out.append(SEPARATOR).append('\n').append("MSG: ").append(d.shortName()).append('\n').append(d.text);
        }
        return out.toString();
    }

    private static void collect(MessageDefinition d, Set<MessageDefinition> seen) {
        if (seen.add(d)) {
            for (MessageDefinition dep : d.dependencies) {
                collect(dep, seen);
            }
        }
    }

    @Override
    public String toString() {
        return name;
    }
}
