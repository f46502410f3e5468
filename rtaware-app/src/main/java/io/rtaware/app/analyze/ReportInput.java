package io.rtaware.app.analyze;

import io.rtaware.app.UserError;
import io.rtaware.core.report.DataReport;
import io.rtaware.core.report.Percentiles;
import io.rtaware.core.report.Report;
import io.rtaware.core.report.TaskReport;
import java.nio.file.Path;

/**
 * Checks a report read from a file before it is analyzed: everything the advice and the
 * schedulability analysis read is there and possible (a file edited by hand, or written by
 * another tool, may lack {@code tasks} or a task's {@code exec_us}, or hold a period of 1e-300
 * ms). The first problem is a {@link UserError} naming the file, the task and the field.
 */
final class ReportInput {

    /** Shortest period or deadline accepted: one nanosecond. */
    static final double MIN_PERIOD_MS = 1e-6;
    /** Longest: a day, in ms. */
    static final double MAX_PERIOD_MS = 86_400_000;

    private ReportInput() {
    }

    /**
     * @param report the report as read
     * @param file where it came from, for the message
     * @throws UserError naming the first problem
     */
    static void check(Report report, Path file) {
        String where = "report " + file;
        if (report.tasks() == null) {
            throw new UserError(where + " has no 'tasks': not a report written by rtaware's --json or run");
        }
        for (TaskReport t : report.tasks()) {
            if (t == null || t.name() == null) {
                throw new UserError(where + ": a task has no 'name'");
            }
            String task = where + ": task '" + t.name() + "'";
            if (t.execUs() == null) {
                throw new UserError(task + " has no 'exec_us' (its execution-time percentiles)");
            }
            checkPercentiles(task, "exec_us", t.execUs());
            checkPeriod(task, "period_ms", t.periodMs());
            checkPeriod(task, "deadline_ms", t.deadlineMs());
        }
        if (report.data() == null) {
            throw new UserError(where + " has no 'data' (the keys' feed statistics; [] when there are none)");
        }
        for (DataReport d : report.data()) {
            if (d == null || d.name() == null || d.producer() == null || d.consumers() == null) {
                throw new UserError(where + ": a key in 'data' lacks 'name', 'producer' or 'consumers'");
            }
            if (!Double.isFinite(d.rateHz()) || d.rateHz() < 0) {
                throw new UserError(where + ": key '" + d.name() + "': 'rate_hz' must be a finite number >= 0, got "
                        + d.rateHz());
            }
        }
    }

    private static void checkPercentiles(String task, String field, Percentiles p) {
        double[] values = {p.p50(), p.p90(), p.p99(), p.max(), p.mean()};
        for (double v : values) {
            if (!Double.isFinite(v) || v < 0) {
                throw new UserError(task + ": '" + field + "' must hold finite numbers >= 0, got " + v);
            }
        }
    }

    private static void checkPeriod(String task, String field, Double ms) {
        if (ms == null) {
            return;
        }
        if (!(ms >= MIN_PERIOD_MS && ms <= MAX_PERIOD_MS)) {
            throw new UserError(task + ": '" + field + "' must be from " + MIN_PERIOD_MS + " ms (1 ns) to "
                    + (long) MAX_PERIOD_MS + " ms (a day), got " + ms);
        }
    }
}
