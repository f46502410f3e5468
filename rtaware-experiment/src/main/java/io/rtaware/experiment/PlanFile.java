package io.rtaware.experiment;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import io.rtaware.core.report.ReportDocument;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;

/**
 * The plan of an experiment as stored in its folder ({@value #FILE_NAME}, schema
 * {@value #SCHEMA}): the whole plan (sets with their periods and top speeds, runs per set,
 * scenario, time scale, seed, grid) and the shard this folder holds, so that
 * {@code experiment --resume --out DIR} continues exactly the experiment that is there and
 * {@code rtaware report DIR...} can tell whether several folders are shares of one plan:
 *
 * <pre>
 * {"schema": "rtaware.experiment-plan/1", "sets": [{"name": "Set 1", "periods_ms": {...}, "top_speed_mps": null}, ...],
 *  "runs_per_set": 10, "scenario": "paper-room", "time_scale": 10.0, "seed": 1, "robot_seed": 1, "robots": 1000,
 *  "design": "independent", "cpu_limit_cpus": null, "grid_resolution_m": null, "shard": "1/2", "order": ["set1-run1", "set2-run1", ...]}
 * </pre>
 *
 * {@code design} ({@link ExperimentDesign}) tells the analysis whether the sets are independent
 * samples or blocked on the run number; a plan without it is {@code blocked}, as every experiment
 * was before it was recorded.
 *
 * {@code order} is the order in which this folder's runs are made (sets interleaved over time,
 * {@link ExperimentPlan#fullOrder()}); it is written for the reader and not read back, since it
 * follows from the rest.
 *
 * A folder made before this file existed gives its plan from {@code experiment.json} and the sets
 * named in {@code results.csv} ({@link #fromFolder}). Stateless.
 */
public final class PlanFile {

    /** The file's name inside an experiment folder. */
    public static final String FILE_NAME = "plan.json";
    /** Its schema. */
    public static final String SCHEMA = "rtaware.experiment-plan/1";

    private static final ObjectMapper MAPPER = ReportDocument.mapper();

    private PlanFile() {
    }

    /**
     * @param dir an experiment folder
     * @param plan its plan and shard
     * @throws IOException if writing fails
     */
    public static void write(Path dir, ExperimentPlan plan) throws IOException {
        ObjectNode root = MAPPER.createObjectNode();
        root.put("schema", SCHEMA);
        var sets = root.putArray("sets");
        for (PeriodSet s : plan.sets()) {
            ObjectNode set = sets.addObject();
            set.put("name", s.name());
            ObjectNode periods = set.putObject("periods_ms");
            s.periodsMs().forEach(periods::put);
            set.put("top_speed_mps", s.topSpeedMps());
        }
        RunConditions c = plan.conditions();
        root.put("runs_per_set", plan.runsPerSet());
        root.put("scenario", c.scenario());
        root.put("time_scale", c.timeScale());
        root.put("seed", c.seed());
        root.put("robot_seed", c.robotSeed());
        root.put("robots", c.robots());
        root.put("design", c.design().label());
        root.put("cpu_limit_cpus", c.cpuLimitCpus());
        if (c.gridResolutionM() == null) {
            root.putNull("grid_resolution_m");
        } else {
            root.put("grid_resolution_m", c.gridResolutionM());
        }
        root.put("shard", plan.shard().toString());
        var order = root.putArray("order");
        plan.order().forEach(p -> order.add(p.folderName()));
        Files.writeString(dir.resolve(FILE_NAME), MAPPER.writerWithDefaultPrettyPrinter().writeValueAsString(root) + "\n");
    }

    /**
     * @param dir an experiment folder
     * @return its stored plan, if {@value #FILE_NAME} is there
     * @throws ExperimentInputException if it is unreadable or malformed (naming the field)
     */
    public static Optional<ExperimentPlan> read(Path dir) {
        Path file = dir.resolve(FILE_NAME);
        if (!Files.exists(file)) {
            return Optional.empty();
        }
        JsonNode root;
        try {
            root = MAPPER.readTree(file.toFile());
        } catch (IOException e) {
            throw new ExperimentInputException(file + ": not valid JSON: " + firstLine(e.getMessage()));
        }
        if (root == null || !SCHEMA.equals(root.path("schema").asText())) {
            throw new ExperimentInputException(file + ": not an rtaware plan (schema is not " + SCHEMA + ")");
        }
        try {
            List<PeriodSet> sets = new ArrayList<>();
            for (JsonNode s : required(root, "sets")) {
                Map<String, Long> periods = new LinkedHashMap<>();
                required(s, "periods_ms").fields().forEachRemaining(e -> periods.put(e.getKey(), e.getValue().asLong()));
                JsonNode speed = s.path("top_speed_mps");
                sets.add(new PeriodSet(required(s, "name").asText(), periods, speed.isNumber() ? speed.asDouble() : null));
            }
            JsonNode grid = root.path("grid_resolution_m");
            JsonNode robotSeed = root.path("robot_seed");
            JsonNode robots = root.path("robots");
            JsonNode design = root.path("design");
            RunConditions conditions = new RunConditions(required(root, "scenario").asText(),
                    required(root, "time_scale").asDouble(), required(root, "seed").asLong(),
                    grid.isNumber() ? grid.asDouble() : null,
                    robotSeed.isNumber() ? robotSeed.asLong() : RunConditions.DEFAULT_ROBOT_SEED,
                    robots.isNumber() ? robots.asInt() : 1,
                    design.isTextual() ? ExperimentDesign.parse(design.asText()) : ExperimentDesign.BLOCKED,
                    root.path("cpu_limit_cpus").isNumber() ? root.path("cpu_limit_cpus").asDouble() : null);
            JsonNode shard = root.path("shard");
            return Optional.of(new ExperimentPlan(sets, required(root, "runs_per_set").asInt(), conditions,
                    shard.isTextual() ? Shard.parse(shard.asText()) : Shard.WHOLE));
        } catch (IllegalArgumentException | ExperimentInputException e) {
            throw new ExperimentInputException(file + ": " + e.getMessage());
        }
    }

    /**
     * The plan of the experiment in a folder: {@value #FILE_NAME}; or, for a folder made before
     * it existed, {@code experiment.json} (scenario, time scale, seed, grid, runs) and the sets of
     * {@code results.csv} (which must name sets 1 to N without a gap, or a set's periods are unknown).
     *
     * @param dir an experiment folder
     * @return its plan
     * @throws IOException if a file cannot be read
     * @throws ExperimentInputException if the folder does not say what its plan was
     */
    public static ExperimentPlan fromFolder(Path dir) throws IOException {
        Optional<ExperimentPlan> stored = read(dir);
        if (stored.isPresent()) {
            return stored.get();
        }
        Path csv = dir.resolve(ResultsCsv.FILE_NAME);
        List<RunResult> rows = Files.exists(csv) ? ResultsCsv.read(csv) : List.of();
        if (rows.isEmpty()) {
            throw new ExperimentInputException(dir + " holds neither " + FILE_NAME + " nor a run in " + ResultsCsv.FILE_NAME
                    + ": nothing tells what to resume");
        }
        TreeMap<Integer, PeriodSet> sets = new TreeMap<>();
        rows.forEach(r -> sets.putIfAbsent(r.set(), r.periods()));
        if (sets.lastKey() != sets.size()) {
            int missing = 1;
            while (sets.containsKey(missing)) {
                missing++;
            }
            throw new ExperimentInputException(dir + " has no " + FILE_NAME + " and " + ResultsCsv.FILE_NAME
                    + " has no run of set " + missing + ", so its periods are unknown; give --sets again without --resume");
        }
        ExperimentProfile profile = ExperimentProfile.read(dir).orElse(ExperimentProfile.fromResults(rows));
        int runs = Math.max(profile.runsPerSet(), rows.stream().mapToInt(RunResult::run).max().orElse(1));
        return new ExperimentPlan(new ArrayList<>(sets.values()), runs, new RunConditions(profile.scenario(),
                profile.timeScale(), profile.seed(), profile.gridResolutionM()));
    }

    private static JsonNode required(JsonNode node, String field) {
        JsonNode n = node.get(field);
        if (n == null || n.isNull()) {
            throw new IllegalArgumentException("field '" + field + "' is missing");
        }
        return n;
    }

    private static String firstLine(String s) {
        return s == null ? "" : s.lines().findFirst().orElse("");
    }
}
