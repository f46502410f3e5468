package io.rtaware.core.report;


/**
 * Checks a report read from a file before it is analyzed: everything the advice and the
 * schedulability analysis read is there and possible (a file edited by hand, or written by
 * another tool, may lack {@code tasks} or a task's {@code exec_us}, or hold a period of 1e-300
 * ms). The first problem is an {@link IllegalArgumentException} naming the file, the task and the field.
 */
public final class ReportChecks {

    /** Shortest period or deadline accepted: one nanosecond. */
    public static final double MIN_PERIOD_MS = 1e-6;
    /** Longest: a day, in ms. */
    public static final double MAX_PERIOD_MS = 86_400_000;

    private ReportChecks() {
    }

    /**
     * @param report the report as read
     * @param file where it came from, for the message
     * @throws IllegalArgumentException naming the first problem
     */
    public static void check(Report report, Object file) {
        String where = "report " + file;
        if (report.tasks() == null) {
            throw new IllegalArgumentException(where + " has no 'tasks': not a report written by rtaware's --json or run");
        }
        for (TaskReport t : report.tasks()) {
            if (t == null || t.name() == null) {
                throw new IllegalArgumentException(where + ": a task has no 'name'");
            }
            String task = where + ": task '" + t.name() + "'";
            if (t.execUs() == null) {
                throw new IllegalArgumentException(task + " has no 'exec_us' (its execution-time percentiles)");
            }
            checkPercentiles(task, "exec_us", t.execUs());
            checkPeriod(task, "period_ms", t.periodMs());
            checkPeriod(task, "deadline_ms", t.deadlineMs());
        }
        if (report.data() == null) {
            throw new IllegalArgumentException(where + " has no 'data' (the keys' feed statistics; [] when there are none)");
        }
        for (DataReport d : report.data()) {
            if (d == null || d.name() == null || d.producer() == null || d.consumers() == null) {
                throw new IllegalArgumentException(where + ": a key in 'data' lacks 'name', 'producer' or 'consumers'");
            }
            if (!Double.isFinite(d.rateHz()) || d.rateHz() < 0) {
                throw new IllegalArgumentException(where + ": key '" + d.name() + "': 'rate_hz' must be a finite number >= 0, got "
                        + d.rateHz());
            }
        }
    }

    private static void checkPercentiles(String task, String field, Percentiles p) {
        double[] values = {p.p50(), p.p90(), p.p99(), p.max(), p.mean()};
        for (double v : values) {
            if (!Double.isFinite(v) || v < 0) {
                throw new IllegalArgumentException(task + ": '" + field + "' must hold finite numbers >= 0, got " + v);
            }
        }
    }

    private static void checkPeriod(String task, String field, Double ms) {
        if (ms == null) {
            return;
        }
        if (!(ms >= MIN_PERIOD_MS && ms <= MAX_PERIOD_MS)) {
            throw new IllegalArgumentException(task + ": '" + field + "' must be from " + MIN_PERIOD_MS + " ms (1 ns) to "
                    + (long) MAX_PERIOD_MS + " ms (a day), got " + ms);
        }
    }
}
