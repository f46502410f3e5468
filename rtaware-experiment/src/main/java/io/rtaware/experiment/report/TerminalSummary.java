package io.rtaware.experiment.report;

import io.rtaware.experiment.ExperimentSummary;
import io.rtaware.experiment.ExperimentSummary.SetSummary;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.Locale;

/**
 * The few lines {@code rtaware experiment} prints when it ends: a busy-machine warning where every
 * run was busy, one row per set (periods, completed runs, run time and distance to the finish as
 * mean +- SD, misses of all four tasks), and where the full report is. Stateless.
 */
public final class TerminalSummary {

    private TerminalSummary() {
    }

    /**
     * @param summary the experiment's summary
     * @param dir its folder
     * @param out where to print
     */
    public static void print(ExperimentSummary summary, Path dir, PrintStream out) {
        out.println();
        if (summary.conditions() != null && summary.conditions().busyOnly()) {
            out.println("BUSY MACHINE: " + summary.conditions().busyLabel());
        }
        out.println("set                     periods (ms)     completed  run time (s)    distance to finish (m)  misses (all four)");
        for (SetSummary s : summary.sets()) {
            out.printf(Locale.ROOT, "%-22s  %-16s %4d/%-4d  %6s +- %-5s  %6s +- %-12s  %s%n", s.name(),
                    String.join("/", s.periodsMs().values().stream().map(String::valueOf).toList()),
                    s.completed(), s.runs(), fmt(s.runTimeS().mean()), fmt(s.runTimeS().sd()),
                    fmt(s.distanceToFinishM().mean()), fmt(s.distanceToFinishM().sd()),
                    pct(s.misses().get(ExperimentSummary.ALL_TASKS).missPct()));
        }
        out.println();
        out.println("report: " + dir.resolve(ExperimentReport.MARKDOWN_FILE) + " (and report.html, summary.json, figures)");
    }

    private static String fmt(Double v) {
        return v == null ? "n/a" : String.format(Locale.ROOT, "%.2f", v);
    }

    private static String pct(Double v) {
        return v == null ? "n/a" : String.format(Locale.ROOT, "%.2f%%", v);
    }
}
