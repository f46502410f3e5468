package io.rtaware.core.report;

import io.rtaware.core.time.Durations;
import java.util.Locale;

/**
 * Renders a {@link Report} as the termination summary a person reads in a terminal: one row
 * per task, one row per data key, and the total miss percentage.
 */
public final class SummaryTable {

    private SummaryTable() {
    }

    /**
     * @param report the report
     * @return the table, lines separated by newlines
     */
    public static String format(Report report) {
        StringBuilder sb = new StringBuilder();
        sb.append(String.format(Locale.ROOT, "rtaware summary: %.3f s of world time (time scale x%s), %.2f%% of all releases missed%n",
                report.durationS(), trim(report.timeScale()), report.missesTotalPct()));
        sb.append(String.format(Locale.ROOT, "%-12s %-10s %8s %8s %8s %8s %7s %7s %7s %6s | %9s %9s %9s | %9s %9s %10s %9s%n",
                "task", "schedule", "period", "releases", "runs", "misses", "miss%", "skipped", "stale", "errors",
                "exec p50", "exec p99", "exec max", "late p50", "late p99", "late p99.9", "late max"));
        for (TaskReport t : report.tasks()) {
            sb.append(String.format(Locale.ROOT, "%-12s %-10s %8s %8d %8d %8d %7.2f %7d %7d %6d | %9s %9s %9s | %9s %9s %10s %9s%n",
                    t.name(), t.schedule(), t.periodMs() == null ? "-" : Durations.formatMillis(t.periodMs()),
                    t.releases(), t.runs(), t.misses(), t.missPct(), t.skipped(), t.staleRuns(), t.errors(),
                    us(t.execUs().p50()), us(t.execUs().p99()), us(t.execUs().max()),
                    us(t.latenessUs().p50()), us(t.latenessUs().p99()), us(t.latenessUs().p999()),
                    us(t.latenessUs().max())));
        }
        if (!report.data().isEmpty()) {
            sb.append(String.format(Locale.ROOT, "%n%-16s %-12s %-28s %8s %9s %10s %10s %10s%n",
                    "data", "producer", "consumers", "commits", "rate", "min int", "mean int", "max int"));
            for (DataReport d : report.data()) {
                sb.append(String.format(Locale.ROOT, "%-16s %-12s %-28s %8d %7.2fHz %8.2fms %8.2fms %8.2fms%n",
                        d.name(), d.producer(), String.join(",", d.consumers()), d.commits(), d.rateHz(),
                        d.intervalMs().min(), d.intervalMs().mean(), d.intervalMs().max()));
            }
        }
        return sb.toString();
    }

    private static String us(double micros) {
        if (micros >= 10_000) {
            return String.format(Locale.ROOT, "%.1fms", micros / 1000);
        }
        return String.format(Locale.ROOT, "%.1fus", micros);
    }

    private static String trim(double v) {
        return v == Math.rint(v) ? Long.toString((long) v) : String.format(Locale.ROOT, "%.3f", v).replaceAll("0+$", "");
    }
}
