package io.rtaware.core.report;

import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.SerializerProvider;
import com.fasterxml.jackson.databind.module.SimpleModule;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import com.fasterxml.jackson.databind.ser.std.StdSerializer;
import java.io.IOException;
import java.util.Iterator;
import java.util.Map;

/**
 * JSON has no NaN or infinity; Jackson writes them as the strings {@code "NaN"} and
 * {@code "Infinity"} by default, which a reader takes for text. Every rtaware JSON writer uses
 * {@link #module()} so that a value a run did not give (NaN) or could not give (an infinity) is
 * written as {@code null}; {@link #clean(JsonNode)} does the same for trees read back from a file.
 */
public final class FiniteNumbers {

    private FiniteNumbers() {
    }

    /** @return a Jackson module writing non-finite {@code double}/{@code float} values as {@code null} */
    public static SimpleModule module() {
        SimpleModule module = new SimpleModule("rtaware-finite-numbers");
        DoubleSerializer doubles = new DoubleSerializer();
        FloatSerializer floats = new FloatSerializer();
        module.addSerializer(Double.class, doubles);
        module.addSerializer(double.class, doubles);
        module.addSerializer(Float.class, floats);
        module.addSerializer(float.class, floats);
        return module;
    }

    /**
     * Replaces every non-finite number in a tree by {@code null}, in place.
     *
     * @param node a tree (objects and arrays are walked)
     * @return the same node
     */
    public static JsonNode clean(JsonNode node) {
        if (node instanceof ObjectNode object) {
            for (Iterator<Map.Entry<String, JsonNode>> it = object.fields(); it.hasNext(); ) {
                Map.Entry<String, JsonNode> field = it.next();
                if (nonFinite(field.getValue())) {
                    field.setValue(object.nullNode());
                } else {
                    clean(field.getValue());
                }
            }
        } else if (node instanceof ArrayNode array) {
            for (int i = 0; i < array.size(); i++) {
                if (nonFinite(array.get(i))) {
                    array.set(i, array.nullNode());
                } else {
                    clean(array.get(i));
                }
            }
        }
        return node;
    }

    private static boolean nonFinite(JsonNode n) {
        return n.isNumber() && (n.isDouble() || n.isFloat()) && !Double.isFinite(n.doubleValue());
    }

    private static final class DoubleSerializer extends StdSerializer<Double> {
        DoubleSerializer() {
            super(Double.class);
        }

        @Override
        public void serialize(Double value, JsonGenerator gen, SerializerProvider provider) throws IOException {
            if (Double.isFinite(value)) {
                gen.writeNumber(value);
            } else {
                gen.writeNull();
            }
        }
    }

    private static final class FloatSerializer extends StdSerializer<Float> {
        FloatSerializer() {
            super(Float.class);
        }

        @Override
        public void serialize(Float value, JsonGenerator gen, SerializerProvider provider) throws IOException {
            if (Float.isFinite(value)) {
                gen.writeNumber(value);
            } else {
                gen.writeNull();
            }
        }
    }
}
