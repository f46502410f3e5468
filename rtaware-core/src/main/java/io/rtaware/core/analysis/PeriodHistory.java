package io.rtaware.core.analysis;

import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.monitor.PeriodChange;
import io.rtaware.core.monitor.TaskInfo;
import io.rtaware.core.task.Schedule;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * One adaptive task's period history, the report's {@code period_history} section (a list of
 * these). Serialized in snake_case. Immutable.
 *
 * @param task the task
 * @param minPeriodMs shortest allowed period, ms
 * @param maxPeriodMs longest allowed period, ms
 * @param initialPeriodMs period at start, ms
 * @param finalPeriodMs period at the end, ms
 * @param changes every change in order
 */
public record PeriodHistory(String task, double minPeriodMs, double maxPeriodMs, double initialPeriodMs,
                            double finalPeriodMs, List<Change> changes) {

    /**
     * Copies the list.
     *
     * @param task the task
     * @param minPeriodMs shortest allowed period, ms
     * @param maxPeriodMs longest allowed period, ms
     * @param initialPeriodMs period at start, ms
     * @param finalPeriodMs period at the end, ms
     * @param changes every change in order
     */
    public PeriodHistory {
        changes = List.copyOf(changes);
    }

    /**
     * @param atS when the new period started, world seconds since the start
     * @param fromMs period before, ms
     * @param toMs period after, ms
     * @param reason {@code misses}, {@code stale} or {@code fresh_with_headroom}
     * @param windowReleases releases in the evaluation window
     * @param windowMisses misses in it
     * @param windowRuns runs in it
     * @param windowStaleRuns stale runs in it
     * @param windowExecMaxMs longest execution time in it, ms
     */
    public record Change(double atS, double fromMs, double toMs, String reason, long windowReleases,
                         long windowMisses, long windowRuns, long windowStaleRuns, double windowExecMaxMs) {
    }

    /**
     * @param monitor a monitor whose task threads have stopped (e.g. in a termination handler)
     * @return the history of every task with a period range, in registration order
     */
    public static List<PeriodHistory> of(Monitor monitor) {
        List<PeriodChange> all = monitor.periodHistory();
        List<PeriodHistory> out = new ArrayList<>();
        for (TaskInfo task : monitor.tasks()) {
            if (!(task.schedule() instanceof Schedule.Periodic p) || !p.isAdaptive()) {
                continue;
            }
            List<Change> changes = all.stream().filter(c -> c.task().equals(task.name()))
                    .map(c -> new Change(c.sinceStartNs() / 1e9, c.fromPeriodNs() / 1e6,
                            c.toPeriodNs() / 1e6, c.reason().name().toLowerCase(Locale.ROOT), c.windowReleases(),
                            c.windowMisses(), c.windowRuns(), c.windowStaleRuns(), c.windowExecMaxNs() / 1e6))
                    .toList();
            double last = changes.isEmpty() ? p.periodNs() / 1e6 : changes.get(changes.size() - 1).toMs();
            out.add(new PeriodHistory(task.name(), p.minPeriodNs() / 1e6, p.maxPeriodNs() / 1e6,
                    p.periodNs() / 1e6, last, changes));
        }
        return out;
    }

    /**
     * @param histories histories
     * @return one line per task and per change, as printed after the summary
     */
    public static String text(List<PeriodHistory> histories) {
        StringBuilder sb = new StringBuilder("adaptive periods:\n");
        for (PeriodHistory h : histories) {
            sb.append(String.format(Locale.ROOT, "  %-12s range %s..%s ms, %s -> %s ms, %d change(s)%n", h.task(),
                    num(h.minPeriodMs()), num(h.maxPeriodMs()), num(h.initialPeriodMs()), num(h.finalPeriodMs()),
                    h.changes().size()));
            for (Change c : h.changes()) {
                sb.append(String.format(Locale.ROOT,
                        "    t=%.3fs %s -> %s ms (%s: %d misses, %d/%d stale, exec max %.3f ms in %d releases)%n",
                        c.atS(), num(c.fromMs()), num(c.toMs()), c.reason(), c.windowMisses(), c.windowStaleRuns(),
                        c.windowRuns(), c.windowExecMaxMs(), c.windowReleases()));
            }
        }
        return sb.toString();
    }

    private static String num(double v) {
        return v == Math.rint(v) ? Long.toString((long) v) : String.format(Locale.ROOT, "%.3f", v).replaceAll("0+$", "");
    }
}
