package io.rtaware.core.report;

import java.util.List;

/**
 * The termination summary of a monitor run, schema {@code rtaware.report/1}. Later layers add
 * sections beside these fields ({@link ReportDocument}); these names never change.
 *
 * @param schema always {@link #SCHEMA}
 * @param timeScale world seconds per wall second during the run
 * @param durationS run length in world seconds
 * @param missesTotalPct misses over all tasks' releases, percent
 * @param tasks per-task timing, in registration order
 * @param data per-key feed statistics, sorted by key name
 * @param frameworkErrors faults on the framework's side up to the report (listeners, the trace
 *     recorder, thread setup, executors), each contained: see
 *     {@code io.rtaware.core.monitor.FrameworkErrorHandler}
 */
public record Report(String schema, double timeScale, double durationS, double missesTotalPct,
                     List<TaskReport> tasks, List<DataReport> data, long frameworkErrors) {

    /**
     * A report without framework faults (for reports built outside a monitor).
     *
     * @param schema always {@link #SCHEMA}
     * @param timeScale world seconds per wall second during the run
     * @param durationS run length in world seconds
     * @param missesTotalPct misses over all tasks' releases, percent
     * @param tasks per-task timing, in registration order
     * @param data per-key feed statistics, sorted by key name
     */
    public Report(String schema, double timeScale, double durationS, double missesTotalPct,
                  List<TaskReport> tasks, List<DataReport> data) {
        this(schema, timeScale, durationS, missesTotalPct, tasks, data, 0);
    }

    /** The schema identifier written in every report. */
    public static final String SCHEMA = "rtaware.report/1";

    /**
     * @param name a task name
     * @return the task's report, or null if there is no such task
     */
    public TaskReport task(String name) {
        return tasks.stream().filter(t -> t.name().equals(name)).findFirst().orElse(null);
    }

    /**
     * @param name a key name
     * @return the key's report, or null if there is no such key
     */
    public DataReport key(String name) {
        return data.stream().filter(d -> d.name().equals(name)).findFirst().orElse(null);
    }
}
