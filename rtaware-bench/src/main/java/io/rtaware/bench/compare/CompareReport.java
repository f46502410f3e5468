package io.rtaware.bench.compare;

import com.fasterxml.jackson.databind.ObjectMapper;
import io.rtaware.core.conditions.Conditions;
import io.rtaware.core.report.ReportDocument;
import java.io.IOException;
import java.io.OutputStream;
import java.util.List;
import java.util.Locale;

/**
 * The result of {@code rtaware bench --compare}, written as JSON with schema
 * {@value #SCHEMA} (names in snake case: {@code period_ms}, {@code lateness_us}, ...).
 *
 * @param schema always {@value #SCHEMA}
 * @param tasks number of tasks
 * @param periodMs period of each task, ms
 * @param workMs CPU work per release, ms
 * @param durationS measured time per executor, s (the sum of its measurement windows)
 * @param segmentS length of one segment, s (executors take turns segment by segment)
 * @param load busy threads competing for the cores ({@code --load})
 * @param gcPressureMbps garbage allocated by a helper thread, MB/s ({@code --gc-pressure})
 * @param java the JVM's version
 * @param gc the collectors in use
 * @param runs one row per executor
 * @param goals the goals checked against the rows
 * @param paired rtaware's executors against their baselines round by round ({@link PairedRounds})
 * @param conditions the machine and JVM over the whole comparison, with the verdict (null if not measured)
 */
public record CompareReport(String schema, int tasks, double periodMs, double workMs, double durationS,
                            double segmentS, int load, double gcPressureMbps, String java, String gc,
                            List<RunResult> runs, List<Goal> goals,
                            List<PairedRounds.Paired> paired, Conditions conditions) {

    /**
     * A report without measured conditions.
     *
     * @param schema always {@value #SCHEMA}
     * @param tasks number of tasks
     * @param periodMs period of each task, ms
     * @param workMs CPU work per release, ms
     * @param durationS measured time per executor, s
     * @param segmentS length of one segment, s
     * @param load busy threads
     * @param gcPressureMbps garbage allocated by a helper thread, MB/s
     * @param java the JVM's version
     * @param gc the collectors in use
     * @param runs one row per executor
     * @param goals the goals checked
     * @param paired the paired rounds
     */
    public CompareReport(String schema, int tasks, double periodMs, double workMs, double durationS, double segmentS,
                         int load, double gcPressureMbps, String java, String gc, List<RunResult> runs,
                         List<Goal> goals, List<PairedRounds.Paired> paired) {
        this(schema, tasks, periodMs, workMs, durationS, segmentS, load, gcPressureMbps, java, gc, runs, goals, paired,
                null);
    }

    /** The JSON schema name. */
    public static final String SCHEMA = "rtaware.bench-compare/1";

    /** rtaware's JSON settings: snake_case, indented, a non-finite number written as null. */
    private static final ObjectMapper MAPPER = ReportDocument.mapper();

    /**
     * @param out where to write the JSON (the stream is not closed)
     * @throws IOException if it cannot be written
     */
    public void write(OutputStream out) throws IOException {
        out.write(MAPPER.writeValueAsBytes(this));
    }

    /** @return the JSON text */
    public String toJson() {
        try {
            return MAPPER.writeValueAsString(this);
        } catch (IOException e) {
            throw new IllegalStateException("cannot serialize the comparison", e);
        }
    }

    /** @return the side-by-side table and the goal lines, for a person */
    public String table() {
        StringBuilder sb = new StringBuilder();
        sb.append(String.format(Locale.ROOT, "compare: %d task(s), period %s ms, work %s ms, %.1f s measured per executor"
                        + " in %.1f s segments; load %d thread(s), gc pressure %s MB/s; %s, %s%n",
                tasks, num(periodMs), num(workMs), durationS, segmentS, load, num(gcPressureMbps), java, gc));
        sb.append(String.format(Locale.ROOT, "%-14s %9s %7s %7s | %9s %9s %9s %9s | %10s %11s%n", "executor",
                "releases", "misses", "bursts", "late p50", "p99", "p99.9", "max", "cpu us/rel", "alloc B/rel"));
        for (RunResult r : runs) {
            RunResult.Lateness l = r.latenessUs();
            sb.append(String.format(Locale.ROOT, "%-14s %9d %7d %7d | %7.1fus %7.1fus %7.1fus %7.1fus | %10.1f %11.1f%n",
                    r.executor(), r.releases(), r.misses(), r.bursts(), l.p50(), l.p99(), l.p999(), l.max(),
                    r.cpuUsPerRelease(), r.allocBytesPerRelease()));
        }
        for (Goal g : goals) {
            sb.append(String.format(Locale.ROOT, "%s goal: %s: %s%n", g.pass() ? "PASS" : "MISS", g.goal(), g.value()));
        }
        for (PairedRounds.Paired p : paired) {
            sb.append("paired: ").append(p.line()).append(System.lineSeparator());
        }
        return sb.toString();
    }

    private static String num(double v) {
        return v == Math.rint(v) ? Long.toString((long) v) : Double.toString(v);
    }
}
