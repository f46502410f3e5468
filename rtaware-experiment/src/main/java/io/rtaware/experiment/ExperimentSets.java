package io.rtaware.experiment;

import com.fasterxml.jackson.core.JacksonException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.dataformat.yaml.YAMLFactory;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The sets of periods an experiment compares: the paper's Table I, or a YAML file of the form
 *
 * <pre>
 * sets:
 *   - name: "Set 1"                 # optional; default "Set i"
 *     periods_ms: {waypoint: 10, obstacle: 10, occupancy: 10, planner: 10}
 *   - name: "fast obstacle"
 *     periods_ms: {waypoint: 100, obstacle: 10, occupancy: 100, planner: 100}
 * </pre>
 *
 * Every set gives a whole, positive number of milliseconds for each of the four tasks
 * ({@link PeriodSet#TASKS}) and nothing else; names are unique. A bad file is reported in one
 * line naming the file, the field and the value.
 */
public final class ExperimentSets {

    /** The value of {@code --sets} that selects Table I of the paper. */
    public static final String PAPER = "paper";

    /** Longest period accepted, in ms: one minute, far above anything a controller uses. */
    public static final long MAX_PERIOD_MS = 60_000;

    private ExperimentSets() {
    }

    /** @return Table I of the paper: Sets 1 to 5 (waypoint/obstacle/occupancy/planner, ms) */
    public static List<PeriodSet> paper() {
        return List.of(
                PeriodSet.of("Set 1", 10, 10, 10, 10),
                PeriodSet.of("Set 2", 100, 10, 100, 100),
                PeriodSet.of("Set 3", 50, 50, 50, 50),
                PeriodSet.of("Set 4", 100, 50, 100, 100),
                PeriodSet.of("Set 5", 100, 100, 100, 100));
    }

    /**
     * @param spec {@link #PAPER} or the path of a YAML sets file
     * @return the sets, in order
     * @throws ExperimentInputException if the file is missing or invalid
     */
    public static List<PeriodSet> resolve(String spec) {
        return PAPER.equals(spec) ? paper() : load(Path.of(spec));
    }

    /**
     * @param file a YAML sets file (format in the class comment)
     * @return the sets, in the file's order
     * @throws ExperimentInputException if the file is missing or invalid
     */
    public static List<PeriodSet> load(Path file) {
        JsonNode root;
        try {
            root = new ObjectMapper(new YAMLFactory()).readTree(Files.readString(file));
        } catch (NoSuchFileException e) {
            throw new ExperimentInputException("sets file " + file + " does not exist (use --sets paper or a YAML file)");
        } catch (JacksonException e) {
            String where = e.getLocation() == null ? "" : " at line " + e.getLocation().getLineNr();
            throw new ExperimentInputException("sets file " + file + " is not valid YAML" + where + ": "
                    + e.getOriginalMessage().lines().findFirst().orElse(""));
        } catch (IOException e) {
            throw new ExperimentInputException("sets file " + file + " cannot be read: " + e.getMessage());
        }
        return parse(file.toString(), root);
    }

    /**
     * @param source the file name used in error messages
     * @param root the parsed document
     * @return the sets
     */
    static List<PeriodSet> parse(String source, JsonNode root) {
        String prefix = "sets file " + source + ": ";
        if (root == null || !root.isObject()) {
            throw new ExperimentInputException(prefix + "expected a mapping with a 'sets' list at the top, got "
                    + describe(root));
        }
        for (var names = root.fieldNames(); names.hasNext(); ) {
            String field = names.next();
            if (!"sets".equals(field)) {
                throw new ExperimentInputException(prefix + "unknown field '" + field + "' (the only top-level field is 'sets')");
            }
        }
        JsonNode sets = root.get("sets");
        if (sets == null || !sets.isArray() || sets.isEmpty()) {
            throw new ExperimentInputException(prefix + "'sets' must be a non-empty list, got " + describe(sets));
        }
        List<PeriodSet> result = new ArrayList<>();
        Set<String> names = new HashSet<>();
        for (int i = 0; i < sets.size(); i++) {
            String at = prefix + "sets[" + i + "]";
            JsonNode set = sets.get(i);
            if (!set.isObject()) {
                throw new ExperimentInputException(at + " must be a mapping with 'name' and 'periods_ms', got " + describe(set));
            }
            for (var fields = set.fieldNames(); fields.hasNext(); ) {
                String field = fields.next();
                if (!"name".equals(field) && !"periods_ms".equals(field)) {
                    throw new ExperimentInputException(at + ": unknown field '" + field + "' (expected name, periods_ms)");
                }
            }
            JsonNode nameNode = set.get("name");
            String name = nameNode == null ? "Set " + (i + 1) : nameNode.asText().strip();
            if (nameNode != null && (!nameNode.isValueNode() || name.isEmpty())) {
                throw new ExperimentInputException(at + ".name must be a non-empty text, got " + describe(nameNode));
            }
            if (!names.add(name)) {
                throw new ExperimentInputException(at + ".name '" + name + "' is used by an earlier set; names must be unique");
            }
            result.add(new PeriodSet(name, periods(at + ".periods_ms", set.get("periods_ms"))));
        }
        return List.copyOf(result);
    }

    private static Map<String, Long> periods(String at, JsonNode node) {
        if (node == null || !node.isObject()) {
            throw new ExperimentInputException(at + " must be a mapping task: ms for " + PeriodSet.TASKS + ", got " + describe(node));
        }
        Map<String, Long> periods = new LinkedHashMap<>();
        for (var fields = node.fields(); fields.hasNext(); ) {
            var field = fields.next();
            String task = field.getKey();
            if (!PeriodSet.TASKS.contains(task)) {
                throw new ExperimentInputException(at + ": unknown task '" + task + "' (tasks: " + String.join(", ", PeriodSet.TASKS) + ")");
            }
            JsonNode value = field.getValue();
            if (!value.canConvertToExactIntegral() || !value.canConvertToLong()
                    || value.asLong() <= 0 || value.asLong() > MAX_PERIOD_MS) {
                throw new ExperimentInputException(at + "." + task + " must be a whole number of ms from 1 to "
                        + MAX_PERIOD_MS + ", got " + describe(value));
            }
            periods.put(task, value.asLong());
        }
        for (String task : PeriodSet.TASKS) {
            if (!periods.containsKey(task)) {
                throw new ExperimentInputException(at + " has no period for task '" + task + "' (every set needs "
                        + String.join(", ", PeriodSet.TASKS) + ")");
            }
        }
        return periods;
    }

    private static String describe(JsonNode node) {
        if (node == null || node.isMissingNode()) {
            return "nothing";
        }
        if (node.isArray()) {
            return "a list";
        }
        if (node.isObject()) {
            return "a mapping";
        }
        if (node.isNull()) {
            return "null";
        }
        return "'" + node.asText() + "'";
    }
}
