package io.rtaware.core.report;

import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * How the periodic tasks' p99 lateness spreads over the tasks of a run: the median task's and
 * the worst task's. With many tasks released at one instant (a pool draining thousands of tasks
 * of one period) each release waits for the ones before it, so the median task waits for about
 * half of the instant's releases and the worst for all of them: these two figures, with the
 * misses, say whether an executor keeps up, where the per-task table is too long to read.
 *
 * @param tasks periodic tasks that were released at least once
 * @param medianP99Us the median over those tasks of each task's p99 lateness, microseconds (the
 *     mean of the two middle ones for an even count)
 * @param worstP99Us the highest of those p99 latenesses, microseconds
 * @param worstTask the task with the highest (the first in registration order among equals)
 * @param missesTotalPct misses over all tasks' releases, percent
 */
public record LatenessSpread(int tasks, double medianP99Us, double worstP99Us, String worstTask,
                             double missesTotalPct) {

    /**
     * @param report a run's report
     * @return the spread over its periodic tasks that were released, or empty if there are none
     */
    public static Optional<LatenessSpread> of(Report report) {
        List<TaskReport> periodic = report.tasks().stream()
                .filter(t -> t.periodMs() != null && t.releases() > 0 && t.latenessUs() != null)
                .toList();
        if (periodic.isEmpty()) {
            return Optional.empty();
        }
        double[] p99 = periodic.stream().mapToDouble(t -> t.latenessUs().p99()).sorted().toArray();
        int n = p99.length;
        double median = n % 2 == 1 ? p99[n / 2] : (p99[n / 2 - 1] + p99[n / 2]) / 2;
        TaskReport worst = periodic.stream().max(Comparator.comparingDouble(t -> t.latenessUs().p99()))
                .orElseThrow();
        return Optional.of(new LatenessSpread(n, median, worst.latenessUs().p99(), worst.name(),
                report.missesTotalPct()));
    }

    /**
     * @return one line, e.g. {@code p99 lateness over 3 periodic tasks: the median task's 3.31
     *     ms, the worst 5.87 ms (b); misses 0.05 % of all releases}
     */
    public String line() {
        return String.format(Locale.ROOT, "p99 lateness over %d periodic task%s: the median task's %.2f ms, the worst"
                        + " %.2f ms (%s); misses %.2f %% of all releases", tasks, tasks == 1 ? "" : "s",
                medianP99Us / 1000, worstP99Us / 1000, worstTask, missesTotalPct);
    }
}
