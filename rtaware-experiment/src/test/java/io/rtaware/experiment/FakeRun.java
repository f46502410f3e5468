package io.rtaware.experiment;

import io.rtaware.core.report.Percentiles;
import io.rtaware.core.report.Report;
import io.rtaware.core.report.ReportDocument;
import io.rtaware.core.report.TaskReport;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A stand-in for {@code rtaware run} started in a child JVM by the runner tests: it writes a
 * report.json and a trajectory.csv whose numbers follow from the periods and the seed. Scenario
 * {@code reject} exits 2 with one line; {@code crash} exits 1 without a report; {@code slow}
 * sleeps a minute (to be interrupted); {@code busy-seed-N} reports the run of seed N as made on
 * a busy machine, the others quiet.
 */
public final class FakeRun {

    private FakeRun() {
    }

    /** @param args {@code run --scenario S --periods ... --seed N --out DIR ...} */
    public static void main(String[] args) throws Exception {
        Map<String, String> opts = new LinkedHashMap<>();
        for (int i = 1; i < args.length; i++) {
            if (args[i].startsWith("--") && i + 1 < args.length && !args[i + 1].startsWith("--")) {
                opts.put(args[i], args[++i]);
            }
        }
        String scenario = opts.get("--scenario");
        if ("reject".equals(scenario)) {
            System.err.println("rtaware: unknown scenario 'reject'");
            System.exit(2);
        }
        if ("crash".equals(scenario)) {
            System.exit(1);
        }
        if ("slow".equals(scenario)) {
            Thread.sleep(60_000);
        }
        Path out = Path.of(opts.get("--out"));
        long seed = Long.parseLong(opts.get("--seed"));
        Map<String, Long> periods = new LinkedHashMap<>();
        for (String p : opts.get("--periods").split(",")) {
            periods.put(p.split("=")[0], io.rtaware.core.time.Durations.parseNanos(p.split("=")[1]) / 1_000_000);
        }
        List<TaskReport> tasks = new ArrayList<>();
        int rank = 0;
        for (Map.Entry<String, Long> e : periods.entrySet()) {
            long releases = 200_000 / e.getValue();
            long misses = releases * (rank + 1) / (e.getValue() + 10);
            tasks.add(new TaskReport(e.getKey(), "periodic", (double) e.getValue(), (double) e.getValue(), releases,
                    releases - misses, misses, 100.0 * misses / releases, misses / 2, rank, 0, 0,
                    new Percentiles(1, 2, 100.0 * (rank + 1), 400, 1), new Percentiles(1, 2, 3, 4, 1)));
            rank++;
        }
        double sum = periods.values().stream().mapToLong(Long::longValue).sum();
        double runTime = 250 + sum / 20 + (seed % 3) * 2.5;
        Map<String, Object> run = new LinkedHashMap<>();
        run.put("scenario", scenario);
        run.put("periods_ms", periods);
        run.put("outcome", "completed");
        run.put("completed", true);
        run.put("run_time_s", runTime);
        run.put("waypoints_reached", 4);
        run.put("waypoints_total", 4);
        run.put("distance_to_finish_m", 0.1 + (seed % 2) * 0.05 + sum / 10_000);
        run.put("distance_travelled_m", 25.0);
        run.put("collisions", 0);
        run.put("mediator", Map.of("obstacle", 1, "waypoint", 2, "stop", 0));
        // One item per task with its bounds (issue 34); waypoint's and planner's in the older shape, one item per rule.
        List<Map<String, Object>> advice = List.of(Map.of("task", "obstacle", "bounds", List.of(
                        Map.of("rule", "exec", "evidence", Map.of("exec_p99_ms", 1.0)),
                        Map.of("rule", "reaction", "evidence", Map.of("max_safe_period_ms", 600.0 + seed)))),
                Map.of("task", "waypoint", "rule", "reaction", "evidence", Map.of("max_safe_period_ms", 42.0)),
                Map.of("task", "planner", "rule", "nyquist", "evidence", Map.of("max_safe_period_ms", 1.0)));
        // Scenario 'busy-seed-N': the run with seed N was made beside another process.
        boolean busy = scenario != null && scenario.equals("busy-seed-" + seed);
        Map<String, Object> conditions = new LinkedHashMap<>();
        conditions.put("machine", busy ? "busy" : "quiet");
        conditions.put("machine_reasons", List.of(busy ? "other processes used 1.2 of 2 CPUs (more than 0.10)"
                : "other processes used 0.02 of 2 CPUs"));
        conditions.put("measured", Map.of("other_cpus", busy ? 1.2 : 0.02, "steal_pct", 0.0, "load_start", busy ? 3.5 : 0.3,
                "load_end", 0.4, "gc_max_pause_ms", 0.1 * seed, "machine_cpus", 2));
        new ReportDocument(new Report(Report.SCHEMA, 1.0, runTime, 1.0, tasks, List.of())).section("run", run)
                .section("advice", advice).section("conditions", conditions).write(out.resolve("report.json"));
        StringBuilder csv = new StringBuilder("t_s,x_m,y_m,yaw_rad\n");
        for (int i = 0; i <= 100; i++) {
            double a = i / 100.0 * Math.PI;
            csv.append(i).append(',').append(4 + 3 * Math.cos(a) + sum / 1000).append(',')
                    .append(3 + 2 * Math.sin(a)).append(",0\n");
        }
        Files.writeString(out.resolve("trajectory.csv"), csv);
    }
}
