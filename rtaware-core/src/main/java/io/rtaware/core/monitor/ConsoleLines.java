package io.rtaware.core.monitor;

import io.rtaware.core.time.Durations;
import java.util.Locale;

/**
 * The text of the {@link ConsoleReporter}'s lines, built on its printer's thread from the counts
 * the reporter's event methods gathered.
 *
 * <p>Why a class of its own: the reporter's event methods run on the task threads, and before
 * HotSpot compiles a method with C2 it resolves every string constant of the method's class not
 * resolved yet, on the thread that asked for the compile (a few hundred bytes for a class with
 * many texts). Kept in the reporter's class, the text of lines never printed yet (an error line,
 * a fold line) would be allocated on a task's thread in steady state when one of the event methods
 * is compiled; here it is allocated on the printer's thread, or never
 * ({@code ReleasePathConstantsTest} checks the reporter's class; {@link OffPathText} is the
 * executors' counterpart).
 */
final class ConsoleLines {

    /** A line's span is shown when it covers more than a second and a half of wall time. */
    private static final long SPAN_SHOWN_ABOVE_NS = 1_500_000_000L;

    private ConsoleLines() {
    }

    /**
     * One task's line.
     *
     * @param task the task's name
     * @param misses deadline misses since its last line
     * @param skipped releases skipped since its last line
     * @param stale stale runs since its last line
     * @param expired expired reads since its last line
     * @param errors errors since its last line
     * @param spanNs the wall time the line covers
     * @param lastDetectedS when the last miss was detected, seconds since the first task started
     * @param lastDeadlineS that miss's deadline, seconds since the first task started
     * @param lastError the last error, or null
     * @param changes period changes since its last line
     * @param lastChange the last period change, or null
     * @return e.g. {@code [rtaware] obstacle: 3 deadline misses in the last 4.0 s, last detected at
     *     t=12.051s (deadline t=12.050s)}
     */
    static String taskLine(String task, long misses, long skipped, long stale, long expired, long errors,
                           long spanNs, double lastDetectedS, double lastDeadlineS, Throwable lastError,
                           long changes, PeriodChange lastChange) {
        StringBuilder sb = new StringBuilder("[rtaware] ").append(task).append(':');
        if (misses + skipped > 0) {
            sb.append(' ').append(misses + skipped).append(misses + skipped == 1 ? " deadline miss" : " deadline misses");
            appendSpan(sb, spanNs);
            if (skipped > 0) {
                sb.append(" (").append(skipped).append(" skipped releases)");
            }
            if (misses > 0) {
                sb.append(String.format(Locale.ROOT, ", last detected at t=%.3fs (deadline t=%.3fs)",
                        lastDetectedS, lastDeadlineS));
            }
        }
        if (stale > 0) {
            sb.append(' ').append(stale).append(stale == 1 ? " stale run" : " stale runs").append(" (no new input)");
        }
        if (expired > 0) {
            sb.append(' ').append(expired).append(" expired reads (input older than its max age)");
        }
        if (errors > 0) {
            sb.append(' ').append(errors).append(errors == 1 ? " error" : " errors");
            if (lastError != null) {
                sb.append(", last: ").append(lastError.getClass().getSimpleName());
                if (lastError.getMessage() != null) {
                    sb.append(": ").append(lastError.getMessage());
                }
            }
        }
        if (changes > 0 && lastChange != null) {
            sb.append(String.format(Locale.ROOT, " period %s -> %s (%s: %d misses, %d/%d stale runs, exec max %s in"
                            + " the last %d releases)", Durations.format(lastChange.fromPeriodNs()),
                    Durations.format(lastChange.toPeriodNs()), lastChange.reason().name().toLowerCase(Locale.ROOT),
                    lastChange.windowMisses(), lastChange.windowStaleRuns(), lastChange.windowRuns(),
                    Durations.format(lastChange.windowExecMaxNs()), lastChange.windowReleases()));
            if (changes > 1) {
                sb.append(" [").append(changes).append(" changes since the last line]");
            }
        }
        return sb.toString();
    }

    /**
     * The line of the tasks over the line budget.
     *
     * @param tasks how many tasks it covers
     * @param misses their deadline misses
     * @param skipped their skipped releases
     * @param stale their stale runs
     * @param expired their expired reads
     * @param errors their errors
     * @param changes their period changes
     * @param spanNs the wall time the line covers
     * @param mostMissesTask the task with the most misses and skipped releases in it, or null if none
     * @param mostMisses that task's misses and skipped releases
     * @param linesPerSecond the budget: most task lines in a wall second
     * @return e.g. {@code [rtaware] 4117 more tasks: 9311 deadline misses; most misses: t802, 4 (at
     *     most 10 task lines a second; each task's counts are in the summary)}
     */
    static String foldLine(int tasks, long misses, long skipped, long stale, long expired, long errors, long changes,
                           long spanNs, String mostMissesTask, long mostMisses, int linesPerSecond) {
        StringBuilder sb = new StringBuilder("[rtaware] ").append(tasks)
                .append(tasks == 1 ? " more task:" : " more tasks:");
        String sep = " ";
        long missed = misses + skipped;
        if (missed > 0) {
            sb.append(sep).append(missed).append(missed == 1 ? " deadline miss" : " deadline misses");
            if (skipped > 0) {
                sb.append(" (").append(skipped).append(" skipped releases)");
            }
            sep = ", ";
        }
        sep = count(sb, sep, stale, " stale run", " stale runs");
        sep = count(sb, sep, expired, " expired read", " expired reads");
        sep = count(sb, sep, errors, " error", " errors");
        count(sb, sep, changes, " period change", " period changes");
        appendSpan(sb, spanNs);
        if (mostMissesTask != null) {
            sb.append("; most misses: ").append(mostMissesTask).append(", ").append(mostMisses);
        }
        return sb.append(" (at most ").append(linesPerSecond)
                .append(" task lines a second; each task's counts are in the summary)").toString();
    }

    private static String count(StringBuilder sb, String sep, long count, String one, String many) {
        if (count == 0) {
            return sep;
        }
        sb.append(sep).append(count).append(count == 1 ? one : many);
        return ", ";
    }

    private static void appendSpan(StringBuilder sb, long spanNs) {
        if (spanNs > SPAN_SHOWN_ABOVE_NS) {
            sb.append(String.format(Locale.ROOT, " in the last %.1f s", spanNs / 1e9));
        }
    }
}
