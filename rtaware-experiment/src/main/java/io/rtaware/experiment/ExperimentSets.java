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
 * The sets of periods an experiment compares: the paper's Table I, a built-in sweep
 * ({@code sweep-obstacle}, {@code sweep-all}), or a YAML file with either a list of sets
 *
 * <pre>
 * sets:
 *   - name: "Set 1"                 # optional; default "Set i"
 *     periods_ms: {waypoint: 10, obstacle: 10, occupancy: 10, planner: 10}
 *   - name: "fast obstacle"
 *     periods_ms: {waypoint: 100, obstacle: 10, occupancy: 100, planner: 100}
 *     top_speed_mps: 0.3            # optional; passed to run as --top-speed
 * </pre>
 *
 * or a sweep ({@link Sweep}: every combination of swept period and top speed)
 *
 * <pre>
 * sweep:
 *   tasks: [obstacle]               # the tasks that take the swept period; default all four
 *   periods_ms: [5, 10, 20, 50, 100, 200, 400, 800]
 *   base_periods_ms: {waypoint: 100} # tasks not swept; default 100 ms each
 *   top_speed_mps: [0.1, 0.3, 0.5]  # optional: one number, or a list to sweep speed too
 * </pre>
 *
 * Every set gives a whole, positive number of milliseconds for each of the four tasks
 * ({@link PeriodSet#TASKS}) and nothing else; names are unique. A bad file is reported in one
 * line naming the file, the field and the value.
 */
public final class ExperimentSets {

    /** The value of {@code --sets} that selects Table I of the paper. */
    public static final String PAPER = "paper";

    /** The value of {@code --sets} that sweeps the obstacle avoider's period, the others at 100 ms. */
    public static final String SWEEP_OBSTACLE = "sweep-obstacle";

    /** The value of {@code --sets} that sweeps the period of all four tasks together. */
    public static final String SWEEP_ALL = "sweep-all";

    /** Longest period accepted, in ms: one minute, far above anything a controller uses. */
    public static final long MAX_PERIOD_MS = 60_000;

    /** Highest top speed accepted, in m/s: a sanity bound far above any indoor robot's. */
    public static final double MAX_TOP_SPEED_MPS = 5.0;

    private static final List<String> SET_FIELDS = List.of("name", "periods_ms", "top_speed_mps");
    private static final List<String> SWEEP_FIELDS = List.of("tasks", "periods_ms", "base_periods_ms", "top_speed_mps");

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
     * @param spec {@link #PAPER}, {@link #SWEEP_OBSTACLE}, {@link #SWEEP_ALL} or the path of a YAML sets file
     * @return the sets, in order
     * @throws ExperimentInputException if the file is missing or invalid
     */
    public static List<PeriodSet> resolve(String spec) {
        return switch (spec) {
            case PAPER -> paper();
            case SWEEP_OBSTACLE -> Sweep.ofPeriods(List.of("obstacle")).sets();
            case SWEEP_ALL -> Sweep.ofPeriods(PeriodSet.TASKS).sets();
            default -> load(Path.of(spec));
        };
    }

    /**
     * @param file a YAML sets file (format in the class comment)
     * @return the sets, in the file's order
     * @throws ExperimentInputException if the file is missing or invalid
     */
    public static List<PeriodSet> load(Path file) {
        JsonNode root;
        try {
            root = new ObjectMapper(new YAMLFactory()).readTree(Utf8Text.read(file, "sets file"));
        } catch (NoSuchFileException e) {
            throw new ExperimentInputException("sets file " + file + " does not exist (use --sets paper, sweep-obstacle, sweep-all or a YAML file)");
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
            throw new ExperimentInputException(prefix + "expected a mapping with a 'sets' list or a 'sweep' at the top, got "
                    + describe(root));
        }
        for (var names = root.fieldNames(); names.hasNext(); ) {
            String field = names.next();
            if (!"sets".equals(field) && !"sweep".equals(field)) {
                throw new ExperimentInputException(prefix + "unknown field '" + field
                        + "' (the top-level field is 'sets' or 'sweep')");
            }
        }
        if (root.has("sets") && root.has("sweep")) {
            throw new ExperimentInputException(prefix + "give either 'sets' or 'sweep', not both");
        }
        if (root.has("sweep")) {
            return sweep(prefix + "sweep", root.get("sweep")).sets();
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
                if (!SET_FIELDS.contains(field)) {
                    throw new ExperimentInputException(at + ": unknown field '" + field + "' (expected "
                            + String.join(", ", SET_FIELDS) + ")");
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
            JsonNode speed = set.get("top_speed_mps");
            result.add(new PeriodSet(name, periods(at + ".periods_ms", set.get("periods_ms"), false),
                    speed == null ? null : speed(at + ".top_speed_mps", speed)));
        }
        return List.copyOf(result);
    }

    private static Sweep sweep(String at, JsonNode node) {
        if (node == null || !node.isObject()) {
            throw new ExperimentInputException(at + " must be a mapping with " + String.join(", ", SWEEP_FIELDS)
                    + ", got " + describe(node));
        }
        for (var fields = node.fieldNames(); fields.hasNext(); ) {
            String field = fields.next();
            if (!SWEEP_FIELDS.contains(field)) {
                throw new ExperimentInputException(at + ": unknown field '" + field + "' (expected "
                        + String.join(", ", SWEEP_FIELDS) + ")");
            }
        }
        List<String> tasks = new ArrayList<>(PeriodSet.TASKS);
        JsonNode tasksNode = node.get("tasks");
        if (tasksNode != null) {
            if (!tasksNode.isArray() || tasksNode.isEmpty()) {
                throw new ExperimentInputException(at + ".tasks must be a non-empty list of tasks (" + String.join(", ",
                        PeriodSet.TASKS) + "), got " + describe(tasksNode));
            }
            tasks.clear();
            for (int i = 0; i < tasksNode.size(); i++) {
                String task = tasksNode.get(i).asText();
                if (!tasksNode.get(i).isTextual() || !PeriodSet.TASKS.contains(task)) {
                    throw new ExperimentInputException(at + ".tasks[" + i + "]: unknown task " + describe(tasksNode.get(i))
                            + " (tasks: " + String.join(", ", PeriodSet.TASKS) + ")");
                }
                if (tasks.contains(task)) {
                    throw new ExperimentInputException(at + ".tasks[" + i + "]: task '" + task + "' is listed twice");
                }
                tasks.add(task);
            }
        }
        List<Long> periods = new ArrayList<>();
        JsonNode periodsNode = node.get("periods_ms");
        if (periodsNode != null) {
            if (!periodsNode.isArray() || periodsNode.isEmpty()) {
                throw new ExperimentInputException(at + ".periods_ms must be a non-empty list of ms, got " + describe(periodsNode));
            }
            for (int i = 0; i < periodsNode.size(); i++) {
                long p = period(at + ".periods_ms[" + i + "]", periodsNode.get(i));
                if (periods.contains(p)) {
                    throw new ExperimentInputException(at + ".periods_ms[" + i + "]: " + p + " ms is listed twice");
                }
                periods.add(p);
            }
        }
        Map<String, Long> base = Sweep.basePeriods();
        JsonNode baseNode = node.get("base_periods_ms");
        if (baseNode != null) {
            base.putAll(periods(at + ".base_periods_ms", baseNode, true));
        }
        List<Double> speeds = new ArrayList<>();
        JsonNode speedNode = node.get("top_speed_mps");
        if (speedNode != null) {
            if (speedNode.isArray()) {
                if (speedNode.isEmpty()) {
                    throw new ExperimentInputException(at + ".top_speed_mps must be a number or a non-empty list, got a list");
                }
                for (int i = 0; i < speedNode.size(); i++) {
                    double v = speed(at + ".top_speed_mps[" + i + "]", speedNode.get(i));
                    if (speeds.contains(v)) {
                        throw new ExperimentInputException(at + ".top_speed_mps[" + i + "]: " + v + " m/s is listed twice");
                    }
                    speeds.add(v);
                }
            } else {
                speeds.add(speed(at + ".top_speed_mps", speedNode));
            }
        }
        if (periods.isEmpty() && speeds.size() < 2) {
            throw new ExperimentInputException(at + " sweeps nothing: give periods_ms (a list), or top_speed_mps as a list "
                    + "of at least two speeds");
        }
        return new Sweep(tasks, periods, base, speeds);
    }

    private static double speed(String at, JsonNode value) {
        if (!value.isNumber() || !(value.asDouble() > 0) || value.asDouble() > MAX_TOP_SPEED_MPS) {
            throw new ExperimentInputException(at + " must be a number of m/s above 0 and at most " + MAX_TOP_SPEED_MPS
                    + ", got " + describe(value));
        }
        return value.asDouble();
    }

    private static long period(String at, JsonNode value) {
        if (!value.canConvertToExactIntegral() || !value.canConvertToLong()
                || value.asLong() <= 0 || value.asLong() > MAX_PERIOD_MS) {
            throw new ExperimentInputException(at + " must be a whole number of ms from 1 to " + MAX_PERIOD_MS
                    + ", got " + describe(value));
        }
        return value.asLong();
    }

    private static Map<String, Long> periods(String at, JsonNode node, boolean partial) {
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
            periods.put(task, period(at + "." + task, field.getValue()));
        }
        for (String task : PeriodSet.TASKS) {
            if (!partial && !periods.containsKey(task)) {
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
