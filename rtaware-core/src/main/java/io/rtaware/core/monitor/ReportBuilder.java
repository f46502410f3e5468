package io.rtaware.core.monitor;

import io.rtaware.core.data.FeedStats;
import io.rtaware.core.data.StateVariable;
import io.rtaware.core.report.DataReport;
import io.rtaware.core.report.Report;
import io.rtaware.core.report.TaskReport;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

/**
 * Builds the termination {@link Report} from the tasks' statistics and the data graph's feeds.
 * Called once, after every task's cycles have stopped. Stateless.
 */
final class ReportBuilder {

    private ReportBuilder() {
    }

    /**
     * @param timeScale the clock's time scale
     * @param durationNs world time from start to stop
     * @param runtimes the tasks, in registration order
     * @param graph the data graph
     * @param frameworkErrors framework faults so far
     * @return the report
     */
    static Report build(double timeScale, long durationNs, List<TaskRuntime> runtimes, DataGraph graph,
                        long frameworkErrors) {
        List<TaskReport> tasks = runtimes.stream().map(TaskRuntime::report).toList();
        long releases = tasks.stream().mapToLong(TaskReport::releases).sum();
        long misses = tasks.stream().mapToLong(TaskReport::misses).sum();
        List<DataReport> data = new ArrayList<>();
        for (StateVariable<?> variable : graph.variables()) {
            String name = variable.key().name();
            FeedStats feed = variable.feedStats();
            data.add(new DataReport(name, graph.producer(name), graph.consumers(name), feed.commits(),
                    TaskRuntime.round2(feed.rateHz()),
                    new DataReport.Interval(ms(feed.minIntervalNs()), ms(feed.meanIntervalNs()),
                            ms(feed.maxIntervalNs()))));
        }
        data.sort(Comparator.comparing(DataReport::name));
        return new Report(Report.SCHEMA, timeScale, Math.round(durationNs / 1e6) / 1e3,
                releases == 0 ? 0.0 : TaskRuntime.round2(100.0 * misses / releases), tasks, data, frameworkErrors);
    }

    private static double ms(double ns) {
        return Math.round(ns / 1e3) / 1e3;
    }
}
