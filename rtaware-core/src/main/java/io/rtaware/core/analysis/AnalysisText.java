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
     * @param advice the advice of a run
     * @return an "advice" block: per task the period, the suggestion and its verdict, the
     *     sentence that says why, and every bound with its figure; then the check of the
     *     suggested periods as one set
     */
    public static String advice(Advice advice) {
        StringBuilder sb = new StringBuilder("advice (one period per task from every rule; bounds in ms):\n");
        if (advice.tasks().isEmpty()) {
            sb.append("  none: no periodic task\n");
        }
        for (PeriodAdvice a : advice.tasks()) {
            sb.append(String.format(Locale.ROOT, "  %-12s %8s -> %-8s %-10s %s%n", a.task(),
                    Durations.formatMillis(a.periodMs()), Durations.formatMillis(a.suggestedPeriodMs()), a.verdict(),
                    a.message()));
            sb.append(String.format(Locale.ROOT, "  %-12s bounds: %s%n", "", bounds(a.bounds())));
            for (AdviceNote note : a.notes()) {
                sb.append(String.format(Locale.ROOT, "  %-12s %s: %s%n", "", note.rule(), note.message()));
            }
        }
        SchedulabilityReport set = advice.suggestedSet();
        if (!set.tasks().isEmpty()) {
            sb.append("  the suggested periods as one set: ").append(set.verdict()).append('\n');
        }
        return sb.toString();
    }

    /**
     * @param bounds bounds of one task
     * @return them in one line: {@code >= 1.2 exec p99; <= 32.092 sampling of 'odometry' (15.58 Hz)}
     */
    static String bounds(List<PeriodBound> bounds) {
        StringBuilder sb = new StringBuilder();
        for (PeriodBound b : bounds) {
            if (sb.length() > 0) {
                sb.append("; ");
            }
            sb.append(b.lower() ? ">= " : "<= ").append(Double.isInfinite(b.ms()) ? "none" : Num.num(b.ms()))
                    .append(' ').append(b.label());
        }
        return sb.toString();
    }

    /**
     * @param s the analysis
     * @return a "schedulability" block: one row per task, the totals and the verdict
     */
    public static String schedulability(SchedulabilityReport s) {
        StringBuilder sb = new StringBuilder(String.format(Locale.ROOT,
                "schedulability (rate-monotonic; utilization C/T; response times on one core, exact, and on %d %s):%n",
                s.cores(), s.cores() == 1 ? "core" : "cores, a sufficient bound"));
        sb.append(String.format(Locale.ROOT, "  %-12s %4s %9s %9s %10s %10s %7s %7s %11s %11s %11s%n", "task", "prio",
                "period", "deadline", "exec p99", "exec max", "U p99", "U max", "resp p99", "resp max",
                "resp p99 " + s.cores() + "c"));
        for (TaskUtilization t : s.tasks()) {
            sb.append(String.format(Locale.ROOT, "  %-12s %4d %9s %9s %10s %10s %7.3f %7.3f %11s %11s %11s%n", t.task(),
                    t.rmPriority(), ms(t.periodMs()), ms(t.deadlineMs()), ms(t.execP99Ms()), ms(t.execMaxMs()),
                    t.utilizationP99(), t.utilizationMax(), response(t.responseP99Ms()),
                    response(t.responseMaxMs()), response(t.responseP99MsOnCores())));
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
