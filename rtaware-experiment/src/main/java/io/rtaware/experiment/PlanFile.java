package io.rtaware.experiment;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
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

/**
 * {@code plan.json} in an experiment folder: the whole plan (sets with their periods and top
 * speeds, runs per set, scenario, time scale, seed, grid) and the shard this folder holds, so
 * that {@code rtaware report DIR...} can tell whether several folders are shares of one plan.
 * Schema {@value #SCHEMA}:
 *
 * <pre>
 * {"schema": "rtaware.experiment-plan/1", "sets": [{"name": "Set 1", "periods_ms": {...}, "top_speed_mps": null}, ...],
 *  "runs_per_set": 10, "scenario": "paper-room", "time_scale": 10.0, "seed": 1, "grid_resolution_m": null,
 *  "shard": "1/2"}
 * </pre>
 */
public final class PlanFile {

    /** The file name inside an experiment folder. */
    public static final String FILE_NAME = "plan.json";
    /** The schema identifier. */
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
        ArrayNode sets = root.putArray("sets");
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
        root.put("grid_resolution_m", c.gridResolutionM());
        root.put("shard", plan.shard().toString());
        Files.writeString(dir.resolve(FILE_NAME), MAPPER.writerWithDefaultPrettyPrinter().writeValueAsString(root) + "\n");
    }

    /**
     * @param dir an experiment folder
     * @return its plan, if {@code plan.json} is there
     * @throws ExperimentInputException if the file is there but not a plan
     */
    public static Optional<ExperimentPlan> read(Path dir) {
        Path file = dir.resolve(FILE_NAME);
        if (!Files.exists(file)) {
            return Optional.empty();
        }
        try {
            JsonNode root = MAPPER.readTree(file.toFile());
            if (root == null || !SCHEMA.equals(root.path("schema").asText())) {
                throw new ExperimentInputException(file + " is not an rtaware plan (schema " + SCHEMA + ")");
            }
            List<PeriodSet> sets = new ArrayList<>();
            for (JsonNode set : root.withArray("sets")) {
                Map<String, Long> periods = new LinkedHashMap<>();
                set.path("periods_ms").fields().forEachRemaining(e -> periods.put(e.getKey(), e.getValue().asLong()));
                JsonNode speed = set.path("top_speed_mps");
                sets.add(new PeriodSet(set.path("name").asText(), periods, speed.isNumber() ? speed.asDouble() : null));
            }
            JsonNode grid = root.path("grid_resolution_m");
            RunConditions c = new RunConditions(root.path("scenario").asText(), root.path("time_scale").asDouble(),
                    root.path("seed").asLong(), grid.isNumber() ? grid.asDouble() : null);
            return Optional.of(new ExperimentPlan(sets, root.path("runs_per_set").asInt(), c,
                    Shard.parse(root.path("shard").asText())));
        } catch (IOException | IllegalArgumentException e) {
            throw new ExperimentInputException(file + " is not a readable rtaware plan: "
                    + String.valueOf(e.getMessage()).lines().findFirst().orElse(""));
        }
    }
}
