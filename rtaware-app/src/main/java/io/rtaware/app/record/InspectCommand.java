package io.rtaware.app.record;

import io.rtaware.app.UserError;
import io.rtaware.app.output.OutputFile;
import io.rtaware.core.output.FigureText;
import io.rtaware.core.output.OutputWrites;
import io.rtaware.core.output.Palette;
import io.rtaware.record.RecordingPlan;
import io.rtaware.record.TaskCycleMessage;
import io.rtaware.record.mcap.McapChannel;
import io.rtaware.record.mcap.McapFormatException;
import io.rtaware.record.mcap.McapReader;
import io.rtaware.record.mcap.McapRecovery;
import io.rtaware.record.mcap.McapSchema;
import io.rtaware.record.mcap.McapSummary;
import io.rtaware.record.mcap.McapVisitor;
import io.rtaware.ros2msg.cdr.CdrException;
import java.awt.BasicStroke;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import org.HdrHistogram.Histogram;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.markers.SeriesMarkers;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code rtaware inspect FILE.mcap}: what a recording holds (channels with types, message
 * counts, rates, time span) and, from its {@code /rtaware/timing/<task>} channels, each task's
 * timing; {@code --plot PNG} draws each task's lateness over time; {@code --recover} writes
 * what an unfinished recording holds to a valid file.
 */
@Command(name = "inspect", mixinStandardHelpOptions = true,
        description = "Summarize an MCAP recording: channels, counts, rates, time span, and each task's timing. "
                + "With --plot, draw each task's lateness over time.")
public final class InspectCommand implements Callable<Integer> {

    private static final long HIGHEST_NS = 3_600_000_000_000L;

    @Parameters(index = "0", paramLabel = "FILE.mcap", description = "A recording (run --record, bench --record).")
    Path file;

    @Option(names = "--plot", paramLabel = "PNG", description = "Write each task's lateness over time to this PNG.")
    Path plot;

    @Option(names = "--recover", description = "Recover an unfinished recording (a run killed, a full disk): write every "
            + "complete chunk to FILE.recovered.mcap and say what was lost.")
    boolean recover;

    /** Per channel: messages and the log-time span. */
    private static final class ChannelStats {
        long messages;
        long firstNs = Long.MAX_VALUE;
        long lastNs = Long.MIN_VALUE;
    }

    /**
     * Per task: what its timing channel says, counted as {@code run}'s summary counts (docs/reports.md):
     * runs, skipped releases, releases (runs plus skipped), misses (runs that ended after their
     * deadline plus skipped releases), stale runs (no input's generation changed since the task's
     * run before) and errors.
     */
    static final class TaskTiming {
        final Histogram latenessNs = new Histogram(1, HIGHEST_NS, 2);
        final Histogram execNs = new Histogram(1, HIGHEST_NS, 2);
        final List<Double> timeS = new ArrayList<>();
        final List<Double> latenessMs = new ArrayList<>();
        long runs;
        long skipped;
        long missedRuns;
        long staleRuns;
        long errors;
        /** The input generations of the run before, for the stale count; none before the first run. */
        long[] lastGenerations;
    }

    @Override
    public Integer call() throws IOException {
        PrintStream out = System.out;
        if (recover) {
            return recover(out);
        }
        if (plot != null) {
            OutputFile.of("--plot", plot); // checked before the file is read: an empty name, a folder, ...
        }
        McapReader reader = open(file);
        McapSummary summary;
        try {
            summary = reader.summary();
        } catch (IOException e) {
            throw McapFiles.unreadable(file, e);
        }
        Map<Integer, String> schemaNames = new HashMap<>();
        for (McapSchema s : summary.schemas()) {
            schemaNames.put(s.id(), s.name() + " (" + s.encoding() + ")");
        }
        Map<Integer, ChannelStats> channels = new LinkedHashMap<>();
        Map<String, TaskTiming> tasks = new LinkedHashMap<>();
        long[] offsetNs = {0};
        long startLogNs = summary.statistics().messageStartNs();
        try {
            reader.read(new McapVisitor() {
                @Override
                public void metadata(String name, Map<String, String> entries) {
                    if (name.equals("rtaware.run")) {
                        offsetNs[0] = parseOffset(entries.get(RecordingPlan.LOG_TIME_OFFSET_NS));
                    }
                }

                @Override
                public void message(McapChannel channel, long sequence, long logTimeNs, long publishTimeNs,
                                    byte[] data, int offset, int length) {
                    ChannelStats c = channels.computeIfAbsent(channel.id(), id -> new ChannelStats());
                    c.messages++;
                    c.firstNs = Math.min(c.firstNs, logTimeNs);
                    c.lastNs = Math.max(c.lastNs, logTimeNs);
                    if (channel.topic().startsWith(RecordingPlan.TIMING_PREFIX)) {
                        String task = channel.topic().substring(RecordingPlan.TIMING_PREFIX.length());
                        timing(tasks.computeIfAbsent(task, t -> new TaskTiming()),
                                TaskCycleMessage.decode(data, offset, length), startLogNs - offsetNs[0]);
                    }
                }
            });
        } catch (CdrException e) {
            throw new UserError(file + ": a timing record is malformed: " + e.getMessage());
        } catch (IOException e) {
            throw McapFiles.unreadable(file, e);
        }

        long startNs = startLogNs - offsetNs[0];
        long endNs = summary.statistics().messageEndNs() - offsetNs[0];
        double spanS = (endNs - startNs) / 1e9;
        out.printf(Locale.ROOT, "%s: %d bytes, %d messages in %d chunks, %d channels, %.3f s of world time "
                        + "(%.3f .. %.3f s)%n", file, reader.sizeBytes(), summary.statistics().messageCount(),
                summary.statistics().chunkCount(), summary.channels().size(), spanS, startNs / 1e9, endNs / 1e9);
        out.println();
        out.printf(Locale.ROOT, "%-32s %-44s %9s %10s%n", "topic", "type", "messages", "rate");
        for (McapChannel ch : summary.channels()) {
            ChannelStats c = channels.getOrDefault(ch.id(), new ChannelStats());
            double rate = spanS > 0 ? c.messages / spanS : 0;
            out.printf(Locale.ROOT, "%-32s %-44s %9d %8.2fHz%n", ch.topic(),
                    schemaNames.getOrDefault(ch.schemaId(), "-"), c.messages, rate);
        }
        if (!tasks.isEmpty()) {
            out.println();
            out.println("task timing (from /rtaware/timing/<task>; world time; counted as run's summary counts:"
                    + " misses = missed runs + skipped):");
            out.printf(Locale.ROOT, "%-12s %8s %8s %8s %11s %8s %8s %6s | %10s %10s %10s | %10s %10s %10s%n", "task",
                    "releases", "runs", "misses", "missed runs", "skipped", "stale", "errors", "late p50", "late p99",
                    "late max", "exec p50", "exec p99", "exec max");
            for (Map.Entry<String, TaskTiming> e : tasks.entrySet()) {
                TaskTiming t = e.getValue();
                out.printf(Locale.ROOT, "%-12s %8d %8d %8d %11d %8d %8d %6d | %10s %10s %10s | %10s %10s %10s%n",
                        e.getKey(), t.runs + t.skipped, t.runs, t.missedRuns + t.skipped, t.missedRuns, t.skipped,
                        t.staleRuns, t.errors, ms(t.latenessNs, 50), ms(t.latenessNs, 99), ms(t.latenessNs, 100),
                        ms(t.execNs, 50), ms(t.execNs, 99), ms(t.execNs, 100));
            }
        }
        if (plot != null) {
            if (tasks.isEmpty()) {
                throw new UserError("--plot: " + file + " has no /rtaware/timing channels to plot");
            }
            OutputWrites writes = new OutputWrites(System.err);
            byte[] png = plotPng(tasks);
            if (writes.writeFile(plot, stream -> stream.write(png))) {
                out.println();
                out.println("lateness plot written to " + plot);
            }
            return writes.exitStatus(0);
        }
        return 0;
    }

    /**
     * @param file a recording
     * @return where {@code --recover} writes what it holds: {@code NAME.recovered.mcap} beside it
     */
    static Path recoveredName(Path file) {
        String name = file.getFileName().toString();
        String base = name.toLowerCase(Locale.ROOT).endsWith(".mcap") ? name.substring(0, name.length() - 5) : name;
        return file.resolveSibling(base + ".recovered.mcap");
    }

    private int recover(PrintStream out) throws IOException {
        Path target = recoveredName(file);
        if (Files.exists(target, LinkOption.NOFOLLOW_LINKS)) {
            throw new UserError("--recover: " + target + " exists; move it away first");
        }
        McapRecovery.Result r;
        try {
            r = McapRecovery.recover(file, target);
        } catch (McapFormatException | java.nio.file.NoSuchFileException e) {
            Files.deleteIfExists(target);
            throw McapFiles.unreadable(file, e);
        } catch (IOException e) {
            Files.deleteIfExists(target);
            throw new UserError("--recover: cannot write " + target + ": " + e.getMessage());
        }
        out.printf(Locale.ROOT, "recovered %d messages in %d complete chunks (log times %d .. %d ns) from %s into %s%n",
                r.messages(), r.chunks(), r.firstLogTimeNs(), r.lastLogTimeNs(), file, target);
        if (r.problem() == null) {
            out.println("lost: nothing (" + file + " was whole)");
        } else if (r.lostBytes() == 0) {
            out.println("lost: no message (every record of " + file + " was read), but " + r.problem());
        } else {
            out.printf(Locale.ROOT, "lost: the last %d of %d bytes, from byte %d: %s%n", r.lostBytes(), r.fileBytes(),
                    r.goodBytes(), r.problem());
        }
        return 0;
    }

    private static McapReader open(Path file) {
        try {
            return McapReader.open(file);
        } catch (IOException e) {
            throw McapFiles.unreadable(file, e);
        }
    }

    /** The log-time offset of the metadata; a value that is not a number counts as none. */
    private static long parseOffset(String value) {
        try {
            return value == null ? 0 : Long.parseLong(value);
        } catch (NumberFormatException e) {
            return 0;
        }
    }

    private static void timing(TaskTiming t, TaskCycleMessage m, long startNs) {
        if (m.outcome().equals("skipped")) {
            t.skipped += m.skippedReleases();
            return;
        }
        t.runs++;
        // One outcome per record, an error before a miss before stale: a run that threw after its
        // deadline counts as an error only. Stale is counted from the generations, as the run counts it.
        t.missedRuns += m.outcome().equals("miss") ? 1 : 0;
        t.errors += m.outcome().equals("error") ? 1 : 0;
        long[] generations = m.inputGenerations();
        long[] last = t.lastGenerations == null ? new long[generations.length] : t.lastGenerations;
        t.staleRuns += generations.length > 0 && Arrays.equals(generations, last) ? 1 : 0;
        t.lastGenerations = generations;
        long lateNs = Math.max(0, m.startNs() - m.releaseNs());
        t.latenessNs.recordValue(Math.min(HIGHEST_NS, Math.max(1, lateNs)));
        t.execNs.recordValue(Math.min(HIGHEST_NS, Math.max(1, m.endNs() - m.startNs())));
        t.timeS.add((m.startNs() - startNs) / 1e9);
        t.latenessMs.add(lateNs / 1e6);
    }

    private static String ms(Histogram h, double percentile) {
        if (h.getTotalCount() == 0) {
            return "-";
        }
        long ns = percentile >= 100 ? h.getMaxValue() : h.getValueAtPercentile(percentile);
        return String.format(Locale.ROOT, "%.3fms", ns / 1e6);
    }

    /**
     * The lateness figure as PNG bytes, written by the caller to exactly the path the user gave
     * (XChart's own file writer appends {@code .png} to any name: {@code --plot /dev/full} wrote
     * {@code /dev/full.png}, {@code --plot ''} wrote {@code ./.png}).
     */
    private static byte[] plotPng(Map<String, TaskTiming> tasks) throws IOException {
        return BitmapEncoder.getBitmapBytes(latenessChart(tasks), BitmapEncoder.BitmapFormat.PNG);
    }

    /** Each task's lateness over time, one colour of {@link Palette} per task, the legend right of the plot. */
    static XYChart latenessChart(Map<String, TaskTiming> tasks) {
        XYChart chart = new XYChartBuilder().width(1000).height(500)
                .title("Release lateness per task (start - release)").xAxisTitle("world time since the first message (s)")
                .yAxisTitle("lateness (ms)").build();
        chart.getStyler().setLegendPosition(org.knowm.xchart.style.Styler.LegendPosition.OutsideE);
        chart.getStyler().setChartBackgroundColor(java.awt.Color.WHITE);
        chart.getStyler().setMarkerSize(2);
        int colour = 0;
        for (Map.Entry<String, TaskTiming> e : tasks.entrySet()) {
            TaskTiming t = e.getValue();
            if (t.timeS.isEmpty()) {
                continue;
            }
            XYSeries s = chart.addSeries(e.getKey(), t.timeS, t.latenessMs);
            s.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Line);
            s.setMarker(SeriesMarkers.NONE);
            s.setLineStyle(new BasicStroke(1f));
            s.setLineColor(Palette.colour(colour++));
        }
        FigureText.fitTitle(chart.getStyler().getChartTitleFont(), chart.getStyler()::setChartTitleFont,
                () -> BitmapEncoder.getBufferedImage(chart), chart.getStyler().getChartPadding());
        return chart;
    }
}
