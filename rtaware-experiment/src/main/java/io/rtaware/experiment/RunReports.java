package io.rtaware.experiment;

import com.fasterxml.jackson.databind.JsonNode;
import io.rtaware.core.report.ReportDocument;
import io.rtaware.core.report.TaskReport;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Turns the {@code report.json} that {@code rtaware run} writes into one {@link RunResult}:
 * the core report's tasks (with their skipped releases, and the largest safe period of the
 * {@code advice} section's {@code reaction} item when there is one) plus the {@code run} section (outcome,
 * run time, distances, collisions, waypoints, and the cycles the mediator gave each winner when
 * the report has a {@code mediator} mapping; a report without it gives none).
 */
public final class RunReports {

    /** The report's file name inside a run's folder. */
    public static final String REPORT_FILE = "report.json";

    private RunReports() {
    }

    /**
     * @param reportFile a run's report.json
     * @param set the set's number
     * @param run the run's number
     * @param periods the set
     * @param conditions the shared conditions
     * @return the run's result
     * @throws IOException if the file is missing, unreadable, or has no {@code run} section
     */
    public static RunResult read(Path reportFile, int set, int run, PeriodSet periods, RunConditions conditions)
            throws IOException {
        ReportDocument doc = ReportDocument.read(reportFile);
        Object section = doc.sections().get("run");
        if (!(section instanceof JsonNode runNode) || !runNode.isObject()) {
            throw new IOException(reportFile + " has no 'run' section");
        }
        Map<String, Double> safe = maxSafePeriods(doc.sections().get("advice"));
        Map<String, TaskResult> tasks = new LinkedHashMap<>();
        for (String name : PeriodSet.TASKS) {
            TaskReport t = doc.report().task(name);
            if (t != null) {
                tasks.put(name, new TaskResult(t.releases(), t.misses(), t.missPct(), t.staleRuns(),
                        t.execUs() == null ? Double.NaN : t.execUs().p99(), t.skipped(), safe.get(name)));
            }
        }
        Map<String, Long> mediator = new LinkedHashMap<>();
        JsonNode mediatorNode = runNode.get("mediator");
        if (mediatorNode != null && mediatorNode.isObject()) {
            for (String winner : RunResult.MEDIATOR_WINNERS) {
                JsonNode v = mediatorNode.get(winner);
                if (v != null && v.isIntegralNumber()) {
                    mediator.put(winner, v.asLong());
                }
            }
        }
        return new RunResult(set, run, periods, conditions, text(runNode, "outcome"),
                number(runNode, "run_time_s"), number(runNode, "distance_to_finish_m"),
                number(runNode, "distance_travelled_m"), integer(runNode, "collisions"),
                integer(runNode, "waypoints_reached"), integer(runNode, "waypoints_total"), tasks, mediator,
                runNode.path("min_clearance_m").isNumber() ? runNode.get("min_clearance_m").asDouble() : null,
                runNode.path("near_misses").isIntegralNumber() ? runNode.get("near_misses").asLong() : null,
                machine(doc.sections().get("conditions")));
    }

    /**
     * @param section the report's {@code conditions} section, or null
     * @return the machine during the run, {@link RunMachine#NOT_RECORDED} without the section
     */
    static RunMachine machine(Object section) {
        if (!(section instanceof JsonNode c) || !c.isObject() || !c.path("machine").isTextual()) {
            return RunMachine.NOT_RECORDED;
        }
        java.util.List<String> reasons = new java.util.ArrayList<>();
        c.path("machine_reasons").forEach(r -> reasons.add(r.asText()));
        JsonNode m = c.path("measured");
        return new RunMachine(c.path("machine").asText(), String.join("; ", reasons), number(m, "other_cpus"),
                number(m, "steal_pct"), number(m, "load_start"), number(m, "load_end"), number(m, "gc_max_pause_ms"),
                number(m, "time_to_safepoint_max_ms"), "", 0, m.path("machine_cpus").asInt(0));
    }

    /**
     * @param advice the report's {@code advice} section (a list of items), or null
     * @return per task, {@code evidence.max_safe_period_ms} of its {@code reaction} bound, or 0 where
     *     the rule finds no safe period (the bound is zero or negative: the input's age and the
     *     stopping distance alone use up the range). Reads both shapes of the section: one item per
     *     task with its {@code bounds} (since issue 34), and one item per rule (before)
     */
    private static Map<String, Double> maxSafePeriods(Object advice) {
        Map<String, Double> safe = new LinkedHashMap<>();
        if (advice instanceof JsonNode items && items.isArray()) {
            for (JsonNode item : items) {
                List<JsonNode> reactions = new ArrayList<>();
                if ("reaction".equals(item.path("rule").asText())) {
                    reactions.add(item);
                }
                item.path("bounds").forEach(b -> {
                    if ("reaction".equals(b.path("rule").asText())) {
                        reactions.add(b);
                    }
                });
                for (JsonNode reaction : reactions) {
                    JsonNode bound = reaction.path("evidence").path("max_safe_period_ms");
                    if (bound.isNumber()) {
                        safe.put(item.path("task").asText(), Math.max(0, bound.asDouble()));
                    }
                }
            }
        }
        return safe;
    }

    private static String text(JsonNode node, String field) throws IOException {
        JsonNode v = node.get(field);
        if (v == null || !v.isTextual()) {
            throw new IOException("run section has no text field '" + field + "'");
        }
        return v.asText();
    }

    private static double number(JsonNode node, String field) {
        JsonNode v = node.get(field);
        return v != null && v.isNumber() ? v.asDouble() : Double.NaN;
    }

    private static Integer integer(JsonNode node, String field) {
        JsonNode v = node.get(field);
        return v != null && v.isNumber() ? v.asInt() : null;
    }
}
