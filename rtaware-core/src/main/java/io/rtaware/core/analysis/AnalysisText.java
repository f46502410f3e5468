package io.rtaware.core.analysis;

import io.rtaware.core.time.Durations;
import java.util.List;
import java.util.Locale;

/**
 * Renders advice and schedulability as the text printed after the termination summary and by
 * {@code rtaware analyze}. Stateless and thread-safe.
 */
public final class AnalysisText {

    private AnalysisText() {
    }

    /**
     * @param advice the advice items
     * @return an "advice" block, one line per item, or a line saying there is none
     */
    public static String advice(List<AdviceItem> advice) {
        StringBuilder sb = new StringBuilder("advice:\n");
        if (advice.isEmpty()) {
            sb.append("  none: every period fits its inputs and its execution time\n");
        }
        for (AdviceItem item : advice) {
            sb.append(String.format(Locale.ROOT, "  %-12s %-16s %8s -> %-8s %s%n", item.task(), item.rule(),
                    Durations.formatMillis(item.periodMs()), Durations.formatMillis(item.suggestedPeriodMs()),
                    item.message()));
        }
        return sb.toString();
    }

    /**
     * @param s the analysis
     * @return a "schedulability" block: one row per task, the totals and the verdict
     */
    public static String schedulability(SchedulabilityReport s) {
        StringBuilder sb = new StringBuilder("schedulability (rate-monotonic, one core; utilization C/T):\n");
        sb.append(String.format(Locale.ROOT, "  %-12s %4s %9s %9s %10s %10s %7s %7s %11s %11s%n", "task", "prio",
                "period", "deadline", "exec p99", "exec max", "U p99", "U max", "resp p99", "resp max"));
        for (TaskUtilization t : s.tasks()) {
            sb.append(String.format(Locale.ROOT, "  %-12s %4d %9s %9s %10s %10s %7.3f %7.3f %11s %11s%n", t.task(),
                    t.rmPriority(), ms(t.periodMs()), ms(t.deadlineMs()), ms(t.execP99Ms()), ms(t.execMaxMs()),
                    t.utilizationP99(), t.utilizationMax(), response(t.responseP99Ms()),
                    response(t.responseMaxMs())));
        }
        if (!s.excludedTasks().isEmpty()) {
            sb.append("  not analyzed (no period): ").append(String.join(", ", s.excludedTasks())).append('\n');
        }
        sb.append(String.format(Locale.ROOT,
                "  total U p99 %.3f, max %.3f; Liu-Layland bound for %d task%s %.3f (%s); per core on %d: p99 %.3f,"
                        + " max %.3f%n",
                s.utilizationP99(), s.utilizationMax(), s.tasks().size(), s.tasks().size() == 1 ? "" : "s",
                s.liuLaylandBound(), s.liuLaylandHoldsP99() ? "holds" : "exceeded", s.cores(),
                s.utilizationPerCoreP99(), s.utilizationPerCoreMax()));
        sb.append("  verdict: ").append(s.verdict()).append('\n');
        return sb.toString();
    }

    private static String ms(double v) {
        return Durations.formatMillis(v);
    }

    private static String response(Double v) {
        return v == null ? "> deadline" : ms(v);
    }
}
