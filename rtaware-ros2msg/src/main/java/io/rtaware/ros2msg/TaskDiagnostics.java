package io.rtaware.ros2msg;

import io.rtaware.core.monitor.TaskCounters;
import io.rtaware.core.monitor.TaskInfo;
import io.rtaware.core.task.Schedule;
import io.rtaware.ros2msg.value.DiagnosticStatus;
import java.util.List;
import java.util.Locale;

/**
 * One {@code diagnostic_msgs/msg/DiagnosticStatus} per task from the monitor's counters, as
 * {@code /diagnostics} carries them (published by the ROS 2 exporter, recorded by the recorder):
 * name {@code rtaware: task <name>}, a message in words (misses, miss %, stale runs, execution-time
 * p99 against the period) and the figures as key/values ({@code schedule}, {@code period_ms},
 * {@code releases}, {@code runs}, {@code misses}, {@code miss_pct}, {@code stale_runs},
 * {@code errors}, {@code exec_p99_ms}, {@code exec_p99_of_period}); level ERROR when errors grew
 * since the last status, WARN when misses did, else OK. Keeps the last counts to tell; one thread.
 */
public final class TaskDiagnostics {

    /** Key/values of a task's status. */
    public static final int VALUES = 10;

    private final long[] lastMisses;
    private final long[] lastErrors;

    /**
     * @param tasks how many tasks (their indexes are {@link TaskInfo#index()})
     */
    public TaskDiagnostics(int tasks) {
        lastMisses = new long[tasks];
        lastErrors = new long[tasks];
    }

    /**
     * Fills a status (cleared, with room for {@value #VALUES} values) for a task.
     *
     * @param task the task
     * @param c its counters now
     * @param s the status to fill
     */
    public void fill(TaskInfo task, TaskCounters c, DiagnosticStatus s) {
        int i = task.index();
        long periodNs = task.schedule() instanceof Schedule.Periodic p ? p.periodNs() : 0;
        double missPct = c.releases() == 0 ? 0.0 : 100.0 * c.misses() / c.releases();
        s.level = c.errors() > lastErrors[i] ? DiagnosticStatus.ERROR
                : c.misses() > lastMisses[i] ? DiagnosticStatus.WARN : DiagnosticStatus.OK;
        lastErrors[i] = c.errors();
        lastMisses[i] = c.misses();
        s.name.append("rtaware: task ").append(task.name());
        s.hardwareId.append("rtaware");
        s.message.append(String.format(Locale.ROOT, "%d misses (%.2f%%), %d stale runs, exec p99 %.3f ms%s",
                c.misses(), missPct, c.staleRuns(), c.recentExecP99Ns() / 1e6,
                periodNs > 0 ? String.format(Locale.ROOT, " of a %.1f ms period", periodNs / 1e6) : ""));
        value(s, "schedule", task.schedule().kind());
        value(s, "period_ms", periodNs > 0 ? format(periodNs / 1e6) : "");
        value(s, "releases", Long.toString(c.releases()));
        value(s, "runs", Long.toString(c.runs()));
        value(s, "misses", Long.toString(c.misses()));
        value(s, "miss_pct", format(missPct));
        value(s, "stale_runs", Long.toString(c.staleRuns()));
        value(s, "errors", Long.toString(c.errors()));
        value(s, "exec_p99_ms", format(c.recentExecP99Ns() / 1e6));
        value(s, "exec_p99_of_period", periodNs > 0 ? format(c.recentExecP99Ns() / (double) periodNs) : "");
    }

    /**
     * Adds a key/value to a status.
     *
     * @param s the status
     * @param key the key
     * @param value the value
     */
    public static void value(DiagnosticStatus s, String key, String value) {
        int i = s.addValue();
        s.key(i).append(key);
        s.value(i).append(value);
    }

    /**
     * @param v a figure
     * @return it with three decimals, or empty if not finite
     */
    public static String format(double v) {
        return Double.isFinite(v) ? String.format(Locale.ROOT, "%.3f", v) : "";
    }

    /**
     * @param tasks the monitor's tasks
     * @return a helper sized for them
     */
    public static TaskDiagnostics of(List<TaskInfo> tasks) {
        return new TaskDiagnostics(tasks.size());
    }
}
