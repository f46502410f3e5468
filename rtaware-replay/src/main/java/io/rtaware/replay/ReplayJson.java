package io.rtaware.replay;

import com.fasterxml.jackson.databind.ObjectMapper;
import io.rtaware.core.report.ReportDocument;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import org.HdrHistogram.Histogram;

/**
 * {@code replay.json} (schema {@value #SCHEMA}) and the table {@code rtaware replay} prints.
 *
 * @param schema {@value #SCHEMA}
 * @param file the recording
 * @param tasks one entry per task replayed
 */
public record ReplayJson(String schema, String file, List<TaskEntry> tasks) {

    /** The schema name. */
    public static final String SCHEMA = "rtaware.replay/1";

    private static final ObjectMapper JSON = ReportDocument.mapper();

    /**
     * One task.
     *
     * @param name the task
     * @param cycles timing records replayed
     * @param identical cycles whose outputs were identical to the recorded ones
     * @param different cycles whose outputs differed
     * @param firstDifference the first difference, or null
     * @param notReplayable cycles that could not be replayed exactly (the recorder dropped a record they need)
     * @param firstNotReplayable the first of them, or null
     * @param inputsMoved input values committed at another time than recorded (a race in the run;
     *     only their age differs)
     * @param execUs execution time per cycle on this machine, microseconds
     */
    public record TaskEntry(String name, long cycles, long identical, long different, FirstDifference firstDifference,
                            long notReplayable, ExactReplay.NotReplayable firstNotReplayable, long inputsMoved,
                            ExecUs execUs) {
    }

    /**
     * @param cycle the cycle's record number in the task's timing channel, from 0
     * @param releaseS its release in world seconds
     * @param key the output key ({@code (cycle)}: threw in one and not the other)
     * @param field the field ({@code (commit)}: committed in one only)
     * @param recorded the recorded value
     * @param replayed the replayed value
     */
    public record FirstDifference(long cycle, double releaseS, String key, String field, String recorded,
                                  String replayed) {
    }

    /**
     * @param p50 median
     * @param p99 99th percentile
     * @param max maximum
     */
    public record ExecUs(double p50, double p99, double max) {
    }

    /**
     * @param file the recording's path
     * @param results the replayed tasks
     * @return the document
     */
    public static ReplayJson of(String file, List<ExactReplay.TaskResult> results) {
        return new ReplayJson(SCHEMA, file, results.stream().map(ReplayJson::entry).toList());
    }

    private static TaskEntry entry(ExactReplay.TaskResult r) {
        ExactReplay.Difference d = r.firstDifference();
        FirstDifference first = d == null ? null
                : new FirstDifference(d.cycle(), d.releaseNs() / 1e9, d.key(), d.field(), d.recorded(), d.replayed());
        Histogram h = r.execNs();
        ExecUs exec = h.getTotalCount() == 0 ? new ExecUs(0, 0, 0)
                : new ExecUs(us(h.getValueAtPercentile(50)), us(h.getValueAtPercentile(99)), us(h.getMaxValue()));
        return new TaskEntry(r.name(), r.cycles(), r.identical(), r.different(), first, r.notReplayable(),
                r.firstNotReplayable(), r.inputsMoved(), exec);
    }

    private static double us(long ns) {
        return Math.round(ns / 100.0) / 10.0;
    }

    /**
     * @param json the document
     * @param file where to write it
     * @throws IOException if it cannot be written
     */
    public static void write(ReplayJson json, Path file) throws IOException {
        Path parent = file.toAbsolutePath().getParent();
        if (parent != null) {
            Files.createDirectories(parent);
        }
        Files.writeString(file, JSON.writeValueAsString(json) + "\n");
    }

    /**
     * @param recording the recording
     * @param json the results
     * @param wallS wall seconds the replay took
     * @return the table and the differences, as printed
     */
    public static String text(Recording recording, ReplayJson json, double wallS) {
        StringBuilder sb = new StringBuilder();
        sb.append(String.format(Locale.ROOT, "exact replay of %s%n", recording.file()));
        sb.append(String.format(Locale.ROOT, "%-10s %8s %10s %10s %14s | %10s %10s %10s%n", "task", "cycles", "identical",
                "different", "not replayable", "exec p50", "exec p99", "exec max"));
        long cycles = 0;
        for (TaskEntry t : json.tasks()) {
            cycles += t.cycles();
            sb.append(String.format(Locale.ROOT, "%-10s %8d %10d %10d %14d | %8.1fus %8.1fus %8.1fus%n", t.name(),
                    t.cycles(), t.identical(), t.different(), t.notReplayable(), t.execUs().p50(), t.execUs().p99(),
                    t.execUs().max()));
        }
        for (TaskEntry t : json.tasks()) {
            FirstDifference d = t.firstDifference();
            if (d != null) {
                sb.append(String.format(Locale.ROOT, "%s: first difference in cycle %d (release %.3f s): key %s, field %s:"
                        + " recorded %s, replayed %s%n", t.name(), d.cycle(), d.releaseS(), d.key(), d.field(),
                        d.recorded(), d.replayed()));
            }
            if (t.inputsMoved() > 0) {
                sb.append(String.format(Locale.ROOT, "%s: %d input values fed at another time than their recorded"
                        + " commit (committed on another thread around this task's cycle start; only their age"
                        + " differs)%n", t.name(), t.inputsMoved()));
            }
            if (t.firstNotReplayable() != null) {
                sb.append(String.format(Locale.ROOT, "%s: not replayable from cycle %d on: %s%n", t.name(),
                        t.firstNotReplayable().cycle(), t.firstNotReplayable().reason()));
            }
        }
        double worldS = worldSpanS(recording);
        sb.append(String.format(Locale.ROOT, "%d cycles replayed in %.2f s of wall time: %.0f cycles/s, %.1f s of"
                + " world time per wall second (exec: wall time of each cycle on this machine)%n", cycles, wallS,
                wallS > 0 ? cycles / wallS : 0, wallS > 0 ? worldS / wallS : 0));
        return sb.toString();
    }

    private static double worldSpanS(Recording recording) {
        long first = Long.MAX_VALUE;
        for (Recording.TaskTimeline t : recording.tasks().values()) {
            if (!t.cycles().isEmpty()) {
                first = Math.min(first, t.cycles().get(0).message().releaseNs());
            }
        }
        return first == Long.MAX_VALUE ? 0 : Math.max(0, recording.endNs() - first) / 1e9;
    }
}
