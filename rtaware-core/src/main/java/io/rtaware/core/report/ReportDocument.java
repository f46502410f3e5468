package io.rtaware.core.report;

import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.JsonMappingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.PropertyNamingStrategies;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ObjectNode;
import io.rtaware.core.output.OutputFiles;
import java.io.IOException;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Objects;

/**
 * A report as written to {@code report.json}: the core {@link Report} plus named sections that
 * other layers add ({@code run}, {@code advice}, {@code schedulability}, ...), each any value
 * Jackson can write. Not thread-safe.
 */
public final class ReportDocument {

    private static final ObjectMapper MAPPER = new ObjectMapper()
            .setPropertyNamingStrategy(PropertyNamingStrategies.SNAKE_CASE)
            .enable(SerializationFeature.INDENT_OUTPUT)
            .disable(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES)
            .registerModule(FiniteNumbers.module());

    private final Report report;
    private final Map<String, Object> sections = new LinkedHashMap<>();

    /** @param report the core report */
    public ReportDocument(Report report) {
        this.report = Objects.requireNonNull(report, "report");
    }

    /** @return the core report */
    public Report report() {
        return report;
    }

    /**
     * Adds or replaces a section written beside the core fields.
     *
     * @param name the section's JSON name, e.g. {@code run}
     * @param value a record, map or JsonNode
     * @return this document
     */
    public ReportDocument section(String name, Object value) {
        sections.put(Objects.requireNonNull(name, "name"), Objects.requireNonNull(value, "value"));
        return this;
    }

    /** @return the sections added, in order */
    public Map<String, Object> sections() {
        return Collections.unmodifiableMap(sections);
    }

    /** @return the document as a JSON tree; a non-finite number (a value the run did not give) is null */
    public ObjectNode toJson() {
        ObjectNode root = MAPPER.valueToTree(report);
        sections.forEach((name, value) -> root.set(name, MAPPER.valueToTree(value)));
        FiniteNumbers.clean(root);
        return root;
    }

    /** @return the document as indented JSON text */
    public String toJsonString() {
        try {
            return MAPPER.writeValueAsString(toJson());
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * @param file where to write the JSON (parent folders are created), whole or not at all
     *     ({@link OutputFiles#write})
     * @throws IOException if writing fails
     */
    public void write(Path file) throws IOException {
        OutputFiles.write(file, this::write);
    }

    /**
     * @param out where to write the JSON, with a line end (the stream is not closed)
     * @throws IOException if writing fails
     */
    public void write(OutputStream out) throws IOException {
        // Streamed, not built as a String first: a report of 10 000 tasks is some 12 MB of text,
        // which as a String, its line-ended copy and its bytes took 80 MB more of a 512 MB heap
        // that the tasks' histograms already fill half of (bench --tasks 10000 ran out of memory).
        MAPPER.writer().without(JsonGenerator.Feature.AUTO_CLOSE_TARGET).writeValue(out, toJson());
        out.write('\n');
    }

    /**
     * Reads a report written by {@link #write(Path)}; sections come back as JSON trees.
     *
     * @param file a report.json
     * @return the document
     * @throws IOException if the file cannot be read or is not a report; a malformed file's
     *     message is one line naming the file and what is wrong in it (where, for bad JSON)
     */
    public static ReportDocument read(Path file) throws IOException {
        JsonNode root;
        Report report;
        try {
            root = MAPPER.readTree(file.toFile());
            if (root == null || !root.isObject() || !Report.SCHEMA.equals(root.path("schema").asText())) {
                throw new IOException(file + ": not an rtaware report (schema is not " + Report.SCHEMA + ")");
            }
            report = MAPPER.treeToValue(root, Report.class);
        } catch (JsonProcessingException e) {
            throw new IOException(file + ": " + problem(e), e);
        }
        ReportDocument doc = new ReportDocument(report);
        for (Map.Entry<String, JsonNode> field : (Iterable<Map.Entry<String, JsonNode>>) root::fields) {
            if (!CORE_FIELDS.contains(field.getKey())) {
                doc.section(field.getKey(), field.getValue());
            }
        }
        return doc;
    }

    /**
     * @param e what Jackson found wrong
     * @return one line for a person: the field or the place, and what is wrong there (Jackson's own
     *     text, without its source dump and its Java type names)
     */
    static String problem(JsonProcessingException e) {
        if (e instanceof JsonMappingException m && !m.getPath().isEmpty()) {
            StringBuilder field = new StringBuilder();
            for (JsonMappingException.Reference r : m.getPath()) {
                if (r.getFieldName() != null) {
                    field.append(field.length() == 0 ? "" : ".").append(r.getFieldName());
                } else {
                    field.append('[').append(r.getIndex()).append(']');
                }
            }
            return "field '" + field + "' does not hold what a report holds there (a number, a text, a list or an "
                    + "object of the schema " + Report.SCHEMA + ")";
        }
        JsonLocation at = e.getLocation();
        String where = at == null || at.getLineNr() < 1 ? "" : " at line " + at.getLineNr() + ", column " + at.getColumnNr();
        String what = String.valueOf(e.getOriginalMessage()).lines().findFirst().orElse("")
                .replaceAll("\\s*\\(start marker at \\[Source.*$", "").replaceAll("\\s*at \\[Source.*$", "");
        return "not valid JSON" + where + ": " + what;
    }

    /**
     * @return the mapper configured for rtaware's JSON (snake_case names, indented, non-finite
     *     numbers as null): every JSON file rtaware writes goes through a copy of it
     */
    public static ObjectMapper mapper() {
        return MAPPER.copy();
    }

    private static final java.util.Set<String> CORE_FIELDS =
            java.util.Set.of("schema", "time_scale", "duration_s", "misses_total_pct", "tasks", "data",
                    "framework_errors");
}
