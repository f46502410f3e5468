package io.rtaware.core.analysis;

import io.rtaware.core.report.DataReport;
import io.rtaware.core.report.Percentiles;
import io.rtaware.core.report.Report;
import io.rtaware.core.report.TaskReport;
import java.util.List;
import java.util.Map;

/** Hand-built reports for the analysis tests. */
final class Reports {

    private Reports() {
    }

    /** A periodic task with the given exec p99/max and mean (us), runs and stale runs. */
    static TaskReport task(String name, double periodMs, double p99Us, double maxUs, double meanUs, long runs,
                           long stale, long misses) {
        return new TaskReport(name, "periodic", periodMs, periodMs, runs, runs, misses,
                runs == 0 ? 0 : 100.0 * misses / runs, 0, stale, 0, 0,
                new Percentiles(meanUs, p99Us, p99Us, maxUs, meanUs), Percentiles.EMPTY);
    }

    /** A periodic task released at {@code offsetMs}, with the given lateness p50 and p99 (us). */
    static TaskReport released(String name, double periodMs, double offsetMs, double lateP50Us, double lateP99Us) {
        return new TaskReport(name, "periodic", periodMs, periodMs, offsetMs, 1000, 1000, 0, 0, 0, 0, 0, 0,
                new Percentiles(1, 2, 3, 4, 1), new Percentiles(lateP50Us, lateP99Us, lateP99Us, lateP99Us, lateP50Us),
                0, null, Map.of());
    }

    /** A continuous task (no period) with the given exec p99 (us). */
    static TaskReport continuous(String name, double p99Us) {
        return new TaskReport(name, "continuous", null, null, 100, 100, 0, 0, 0, 0, 0, 0,
                new Percentiles(p99Us, p99Us, p99Us, p99Us, p99Us), Percentiles.EMPTY);
    }

    static DataReport key(String name, String producer, double rateHz, String... consumers) {
        return new DataReport(name, producer, List.of(consumers), 100, rateHz,
                new DataReport.Interval(1000 / rateHz, 1000 / rateHz, 1000 / rateHz));
    }

    static Report report(List<TaskReport> tasks, List<DataReport> data) {
        return new Report(Report.SCHEMA, 1.0, 10.0, 0.0, tasks, data);
    }
}
