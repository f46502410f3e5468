package io.rtaware.app.replay;

import io.rtaware.app.UserError;
import io.rtaware.app.output.OutputFolder;
import io.rtaware.app.record.McapFiles;
import io.rtaware.app.run.TaskPeriods;
import io.rtaware.core.analysis.ReportSections;
import io.rtaware.core.report.ReportDocument;
import io.rtaware.core.report.SummaryTable;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.Durations;
import io.rtaware.nav.ControllerMetadata;
import io.rtaware.record.mcap.McapFormatException;
import io.rtaware.record.mcap.McapReader;
import io.rtaware.replay.ExactReplay;
import io.rtaware.replay.Recording;
import io.rtaware.replay.ReplayJson;
import io.rtaware.replay.ReplayProviders;
import io.rtaware.replay.WhatIfReplay;
import java.io.File;
import java.io.IOException;
import java.io.PrintStream;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.ServiceConfigurationError;
import java.util.concurrent.Callable;
import java.util.function.Supplier;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code rtaware replay FILE.mcap [--classpath PATHS]}: a recording of any replayable controller
 * ({@code rtaware run --record}, or a user's controller recorded with
 * {@link io.rtaware.replay.ReplayableController#describe}) re-executed offline. Without
 * {@code --periods}: exact re-execution of every recorded cycle of the controller's tasks
 * ({@link ExactReplay}), compared with the recorded outputs; with {@code --periods}: the
 * controller with other periods on the recorded sensor stream ({@link WhatIfReplay}), reported
 * as a run is. The controller is rebuilt by the replay provider the recording names, found with
 * {@link java.util.ServiceLoader} among the command's own classes and those of {@code --classpath}
 * ({@link ReplayProviders}).
 */
@Command(name = "replay", mixinStandardHelpOptions = true,
        description = {"Re-execute a recording of a replayable controller offline ('rtaware run --record', or your own "
                + "controller's recording: pass its classes and their replay provider with --classpath).",
                "Exact (default): feed every recorded cycle of the controller's tasks the inputs it read, run it on the "
                + "step executor, and compare its outputs with the recorded ones (a difference means the behavior "
                + "depends on something besides its inputs).",
                "What-if (--periods): run the controller with other periods on the recorded sensor stream, charging "
                + "each cycle a recorded execution time, and report as 'run' does (open loop)."})
public final class ReplayCommand implements Callable<Integer> {

    @Parameters(index = "0", paramLabel = "FILE.mcap", description = "A recording (run --record).")
    Path file;

    @Option(names = "--task", paramLabel = "NAME", description = "Replay only this task (exact replay).")
    String task;

    @Option(names = "--out", paramLabel = "DIR",
            description = "Write replay.json (exact) or report.json (what-if) into this folder.")
    Path out;

    /** Most cycles a what-if replay makes: about a minute of replay on a 2-core machine. */
    static final long MAX_WHAT_IF_CYCLES = 20_000_000L;

    @Option(names = "--periods", paramLabel = "TASK=DURATION,...",
            description = "What-if: periods to try, e.g. planner=50ms (tasks not named keep the recorded periods).")
    String periods;

    @Option(names = "--classpath", paramLabel = "PATHS",
            description = "Where your controller's classes and its replay provider are: folders and jars, separated by"
                    + " the system's path separator (':' on Linux and macOS).")
    String classpath;

    @Override
    public Integer call() throws IOException {
        try (URLClassLoader loader = new URLClassLoader(classpathUrls(classpath), ReplayCommand.class.getClassLoader())) {
            return replay(loader);
        }
    }

    /** The {@code --classpath} entries as URLs; a missing one is one line and status 2. */
    private static URL[] classpathUrls(String classpath) {
        if (classpath == null) {
            return new URL[0];
        }
        List<URL> urls = new ArrayList<>();
        for (String entry : classpath.split(File.pathSeparator)) {
            if (entry.isBlank()) {
                continue;
            }
            Path path = Path.of(entry);
            if (!Files.exists(path)) {
                throw new UserError("--classpath: no such file or directory: " + entry);
            }
            try {
                urls.add(path.toUri().toURL());
            } catch (MalformedURLException e) {
                throw new UserError("--classpath: not a usable path: " + entry + " (" + e.getMessage() + ")");
            }
        }
        return urls.toArray(new URL[0]);
    }

    private int replay(ClassLoader loader) {
        if (task != null && periods != null) {
            throw new UserError("--task and --periods exclude each other (--task selects a task for exact replay)");
        }
        if (out != null) {
            OutputFolder.of("--out", out);
        }
        Recording recording = load(file);
        if (recording.tasks().isEmpty()) {
            throw new UserError(file + " has no /rtaware/timing channels: not a recording of 'rtaware run --record'");
        }
        ReplayProviders.RecordedController controller;
        List<String> names;
        try {
            controller = ReplayProviders.load(loader).controllerOf(recording.runMetadata());
            names = controller.tasks(Map.of()).stream().map(TaskSpec::name).toList();
        } catch (IllegalArgumentException | ServiceConfigurationError e) {
            throw new UserError(file + ": " + e.getMessage());
        }
        List<String> known = new ArrayList<>(); // in the controller's order, as run reports them
        for (String name : names) {
            if (recording.tasks().containsKey(name)) {
                known.add(name);
            }
        }
        if (known.isEmpty()) {
            throw new UserError(file + " has no cycles of the controller's tasks (" + String.join(", ", names) + ")");
        }
        PrintStream stdout = System.out;
        try {
            if (periods != null) {
                return whatIf(recording, controller, names, stdout);
            }
            if (task != null && !known.contains(task)) {
                throw new UserError("unknown task '" + task + "' in " + file + "; tasks: " + String.join(", ", known));
            }
            return exact(recording, controller, task == null ? known : List.of(task), stdout);
        } catch (McapFormatException e) {
            throw new UserError(e.getMessage());
        } catch (IOException e) {
            throw new UserError(file + ": " + e.getMessage());
        }
    }

    /**
     * @param file a recording
     * @return it, loaded
     * @throws UserError in one line if it cannot be read, is not MCAP, or does not fit in the heap
     */
    public static Recording load(Path file) {
        try {
            return Recording.load(McapReader.open(file), file);
        } catch (IOException e) {
            throw McapFiles.unreadable(file, e);
        } catch (RuntimeException e) {
            // A malformed file the reader did not anticipate (e.g. a compressed chunk that breaks the decompressor).
            throw new UserError(file + ": not a readable MCAP recording (" + e + ")");
        } catch (OutOfMemoryError e) {
            throw new UserError(file + " does not fit in this JVM's heap (" + Runtime.getRuntime().maxMemory() / (1 << 20)
                    + " MB); give it more with RTAWARE_JAVA_OPTS=-Xmx...");
        }
    }

    private int exact(Recording recording, ReplayProviders.RecordedController recorded, List<String> tasks,
                      PrintStream stdout) throws IOException {
        Supplier<List<TaskSpec>> controller = () -> recorded.tasks(Map.of());
        long wallStart = System.nanoTime();
        List<ExactReplay.TaskResult> results = new ArrayList<>();
        for (String name : tasks) {
            results.add(ExactReplay.replay(recording, controller, name));
        }
        double wallS = (System.nanoTime() - wallStart) / 1e9;
        ReplayJson json = ReplayJson.of(recording.file().toString(), results);
        stdout.print(ReplayJson.text(recording, json, wallS));
        if (out != null) {
            Path target = out.resolve("replay.json");
            try {
                ReplayJson.write(json, target);
            } catch (IOException e) {
                throw new UserError("cannot write " + target + ": " + e.getMessage());
            }
            stdout.println("replay written to " + target);
        }
        return 0;
    }

    /**
     * Refuses periods that would make the replay run for hours without a word (issue 24: a
     * planner period of 10 ns over a recording of minutes): one line with the cycle count, the
     * budget and the shortest period the budget allows.
     */
    private static void checkCycleBudget(Recording recording, Map<String, Long> periodsNs) {
        double worldNs = Math.max(1, recording.endNs());
        double cycles = 0;
        for (long periodNs : periodsNs.values()) {
            cycles += worldNs / periodNs;
        }
        if (cycles > MAX_WHAT_IF_CYCLES) {
            Map.Entry<String, Long> shortest = periodsNs.entrySet().stream().min(Map.Entry.comparingByValue()).orElseThrow();
            throw new UserError(String.format(Locale.ROOT, "--periods: %s=%s over the recording's %.1f s of world time makes"
                            + " %.3g cycles; a what-if replay makes at most %.0e (give '%s' a period of at least %s)",
                    shortest.getKey(), Durations.format(shortest.getValue()), worldNs / 1e9, cycles,
                    (double) MAX_WHAT_IF_CYCLES, shortest.getKey(),
                    Durations.format((long) Math.ceil(worldNs * periodsNs.size() / MAX_WHAT_IF_CYCLES))));
        }
    }

    private int whatIf(Recording recording, ReplayProviders.RecordedController recorded, List<String> names,
                       PrintStream stdout) throws IOException {
        Map<String, Long> recordedNs = recorded.recordedPeriodsNs();
        TaskPeriods defaults = TaskPeriods.ofNanos(recordedNs);
        TaskPeriods asked = TaskPeriods.parse(periods, defaults);
        Map<String, Long> changed = new LinkedHashMap<>(); // only what differs: the controller derives the rest
        asked.nanosByTask().forEach((name, ns) -> {
            if (!ns.equals(recordedNs.get(name))) {
                changed.put(name, ns);
            }
        });
        List<TaskSpec> tasks;
        try {
            tasks = recorded.tasks(changed);
        } catch (IllegalArgumentException e) {
            throw new UserError("--periods: " + e.getMessage());
        }
        TaskPeriods run = TaskPeriods.ofNanos(ReplayProviders.periodsNs(tasks)); // with what the controller derives
        checkCycleBudget(recording, run.nanosByTask());
        long wallStart = System.nanoTime();
        WhatIfReplay.Result result = WhatIfReplay.replay(recording, tasks, recorded.tasks(changed));
        double wallS = (System.nanoTime() - wallStart) / 1e9;
        int cores = cores(recording);
        ReportDocument doc = new ReportDocument(result.report());
        Map<String, Object> section = new LinkedHashMap<>();
        section.put("file", recording.file().toString());
        section.put("mode", "what-if");
        section.put("open_loop", true);
        section.put("periods_ms", run.millis());
        section.put("recorded_periods_ms", defaults.millis());
        section.put("sensor_keys", result.sensorKeys());
        section.put("sensor_commits", result.sensorCommits());
        section.put("exec_time", "each task's recorded execution times in order, starting over when they run out");
        section.put("cores", cores);
        doc.section("replay", section);
        String analysis = ReportSections.enrich(doc, cores).text();
        stdout.print(SummaryTable.format(result.report()));
        stdout.println();
        long cycles = result.report().tasks().stream().filter(t -> names.contains(t.name()))
                .mapToLong(t -> t.runs()).sum();
        String fed = result.sensorKeys().isEmpty() ? "no recorded values fed (the controller produces every key it reads)"
                : String.format(Locale.ROOT, "%d values of %s fed by '%s' at their recorded times", result.sensorCommits(),
                        String.join(", ", result.sensorKeys()), result.dataTask());
        stdout.printf(Locale.ROOT, "what-if replay of %s with periods %s (recorded: %s): open loop, the robot's path is the"
                        + " recorded one; %s; each cycle charged its task's recorded execution times in order; one core"
                        + " (step executor)%n", recording.file(), run, defaults, fed);
        stdout.printf(Locale.ROOT, "%d cycles, %.1f s of world time in %.2f s of wall time: %.0f cycles/s, %.1f s of world"
                + " time per wall second%n", cycles, result.report().durationS(), wallS, wallS > 0 ? cycles / wallS : 0,
                wallS > 0 ? result.report().durationS() / wallS : 0);
        stdout.println();
        stdout.print(analysis);
        if (out != null) {
            Path target = out.resolve("report.json");
            try {
                doc.write(target);
            } catch (IOException e) {
                throw new UserError("cannot write " + target + ": " + e.getMessage());
            }
            stdout.println("report written to " + target);
        }
        return 0;
    }

    private static int cores(Recording recording) {
        String recorded = recording.runMetadata().get(ControllerMetadata.CORES);
        try {
            return recorded == null ? Runtime.getRuntime().availableProcessors() : Math.max(1, Integer.parseInt(recorded));
        } catch (NumberFormatException e) {
            return Runtime.getRuntime().availableProcessors();
        }
    }
}
