package io.rtaware.experiment;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Clock;
import java.time.Instant;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Objects;
import java.util.Set;
import java.util.concurrent.TimeUnit;

/**
 * Makes the runs of a plan one at a time, each in its own process, in interleaved order, and
 * appends each finished run to {@code results.csv} at once. Runs already in the file are skipped,
 * so re-running into the same folder resumes. With a {@link QuietGate}, each run waits for a quiet
 * machine first and its row records the check. {@link #interrupt()} (from a shutdown hook) stops
 * the run under way and ends the loop; the folder stays valid.
 *
 * <p>Layout of the output folder: {@code results.csv}, {@code plan.json} (the plan and shard,
 * written once the folder's rows are found to match them), and {@code runs/setI-runJ/} per run
 * with the run's {@code report.json}, {@code trajectory.csv} and {@code run.log} (its output).
 */
public final class ExperimentRunner {

    /** The folder holding one sub-folder per run. */
    public static final String RUNS_DIR = "runs";
    /** The file in each run's folder that receives the run's stdout and stderr. */
    public static final String LOG_FILE = "run.log";
    /** Name of a run's recording in its folder, with {@link #recordEachRun(boolean)}. */
    public static final String RECORDING_FILE = "run.mcap";

    private static final long STOP_GRACE_S = 10;
    private static final int EXIT_SIGINT = 130;
    private static final int EXIT_SIGTERM = 143;

    private final ExperimentPlan plan;
    /**
     * The environment variable through which each run learns the pid of the experiment that
     * started it: a run whose experiment is gone (killed, even with SIGKILL, which no shutdown
     * hook sees) stops the robot, writes its report and exits, instead of writing into a folder
     * that a resumed experiment may fill again beside it.
     */
    public static final String PARENT_PID_ENV = "RTAWARE_EXPERIMENT_PID";

    private final RunCommand command;
    private final Path outDir;
    private final ProgressBar progress;
    private volatile boolean interrupted;
    private volatile Process current;
    private boolean record;
    private QuietGate gate;
    private Clock clock = Clock.systemUTC();

    /**
     * @param plan the runs to make
     * @param command how to start one run
     * @param outDir the experiment folder (created if missing)
     * @param progress where progress goes
     */
    public ExperimentRunner(ExperimentPlan plan, RunCommand command, Path outDir, ProgressBar progress) {
        this.plan = Objects.requireNonNull(plan, "plan");
        this.command = Objects.requireNonNull(command, "command");
        this.outDir = Objects.requireNonNull(outDir, "outDir");
        this.progress = Objects.requireNonNull(progress, "progress");
    }

    /** @return the results file of this experiment */
    public Path resultsFile() {
        return outDir.resolve(ResultsCsv.FILE_NAME);
    }

    /**
     * Makes every run of the plan that is not yet in {@code results.csv}.
     *
     * @return every row of {@code results.csv} when the loop ends (finished or interrupted)
     * @throws IOException if the folder cannot be written
     * @throws InterruptedException if this thread is interrupted while waiting for a run
     * @throws ExperimentInputException if the folder holds results of other settings, or
     *     {@code run} rejects its arguments (exit status 2)
     */
    public List<RunResult> run() throws IOException, InterruptedException {
        Files.createDirectories(outDir.resolve(RUNS_DIR));
        Path csv = resultsFile();
        List<ResultsCsv.Row> existing = Files.exists(csv) ? ResultsCsv.readRows(csv) : List.of();
        ResultsCsv.tornLastLine(csv).ifPresent(progress::note);
        Set<String> done = new HashSet<>();
        for (ResultsCsv.Row row : existing) {
            RunResult r = row.result();
            checkMatchesPlan(r, row.line());
            done.add(r.set() + "/" + r.run());
        }
        PlanFile.write(outDir, plan);
        List<PlannedRun> order = plan.order();
        int total = order.size();
        int finished = (int) order.stream().filter(p -> done.contains(p.set() + "/" + p.run())).count();
        if (finished > 0) {
            progress.note("resuming: " + finished + " of " + total + " runs already in " + csv);
        }
        for (PlannedRun planned : order) {
            if (interrupted) {
                break;
            }
            if (done.contains(planned.set() + "/" + planned.run())) {
                continue;
            }
            QuietGate.Passage passage = gate == null ? null : gate.await(progress, () -> interrupted);
            if (interrupted) {
                break;
            }
            progress.started(planned, finished, total);
            Instant started = clock.instant();
            RunResult result = runOne(planned);
            if (result == null) {
                break;
            }
            result = result.withTimes(new RunTimes(started, clock.instant()));
            if (passage != null) {
                result = result.withMachine(result.machine().withCheck(passage));
            }
            ResultsCsv.append(csv, result);
            finished++;
            progress.finished(result, finished, total);
        }
        progress.close();
        return Files.exists(csv) ? ResultsCsv.read(csv) : List.of();
    }

    /**
     * Stops the run under way (SIGTERM, then a forced kill after a grace period) and makes
     * {@link #run()} return after it. Safe to call from a shutdown hook.
     */
    public void interrupt() {
        interrupted = true;
        Process p = current;
        if (p != null && p.isAlive()) {
            p.destroy();
            try {
                if (!p.waitFor(STOP_GRACE_S, TimeUnit.SECONDS)) {
                    p.destroyForcibly();
                }
            } catch (InterruptedException e) {
                p.destroyForcibly();
                Thread.currentThread().interrupt();
            }
        }
    }

    /** @return true once {@link #interrupt()} was called or a run reported it was interrupted */
    public boolean interrupted() {
        return interrupted;
    }

    /**
     * @param quietGate checks the machine before each run and waits for it to be quiet (null: no check)
     * @return this runner
     */
    public ExperimentRunner quietGate(QuietGate quietGate) {
        this.gate = quietGate;
        return this;
    }

    /**
     * @param wallClock the clock whose instants are each run's {@code started_utc} and {@code ended_utc}
     *     (default: the system's, in UTC)
     * @return this runner
     */
    public ExperimentRunner clock(Clock wallClock) {
        this.clock = Objects.requireNonNull(wallClock, "wallClock");
        return this;
    }

    /**
     * @param enabled true to record each run to {@link #RECORDING_FILE} in its folder ({@code run --record})
     * @return this runner
     */
    public ExperimentRunner recordEachRun(boolean enabled) {
        this.record = enabled;
        return this;
    }

    private RunResult runOne(PlannedRun planned) throws IOException, InterruptedException {
        Path runDir = outDir.resolve(RUNS_DIR).resolve(planned.folderName());
        deleteRecursively(runDir);
        Files.createDirectories(runDir);
        Path log = runDir.resolve(LOG_FILE);
        List<String> arguments = new ArrayList<>(plan.runArguments(planned, runDir));
        if (record) {
            arguments.addAll(List.of("--record", runDir.resolve(RECORDING_FILE).toString()));
        }
        List<String> cmd = command.commandLine(arguments);
        ProcessBuilder builder = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log.toFile());
        // The run stops by itself when this process is gone, even killed with SIGKILL (issue 24).
        builder.environment().put(PARENT_PID_ENV, Long.toString(ProcessHandle.current().pid()));
        Process p = builder.start();
        current = p;
        int exit;
        try {
            exit = p.waitFor();
        } catch (InterruptedException e) {
            p.destroyForcibly();
            throw e;
        } finally {
            current = null;
        }
        if (interrupted || exit == EXIT_SIGINT || exit == EXIT_SIGTERM) {
            // Ctrl-C reaches the run too (same process group): an interrupted run is not a result.
            interrupted = true;
            return null;
        }
        if (exit == 2) {
            throw new ExperimentInputException("rtaware run rejected its arguments (set " + planned.set() + " run "
                    + planned.run() + ", exit status 2): " + lastLine(log) + " (full output: " + log + ")");
        }
        Path report = runDir.resolve(RunReports.REPORT_FILE);
        if (exit != 0 || !Files.exists(report)) {
            progress.note("run set " + planned.set() + " run " + planned.run() + " failed (exit status " + exit
                    + (Files.exists(report) ? "" : ", no report.json") + "); recorded as 'error', see " + log);
            return RunResult.error(planned.set(), planned.run(), planned.periods(), plan.conditions());
        }
        RunResult result;
        try {
            result = RunReports.read(report, planned.set(), planned.run(), planned.periods(), plan.conditions());
        } catch (IOException | RuntimeException e) {
            progress.note("run set " + planned.set() + " run " + planned.run() + ": unreadable report (" + e.getMessage()
                    + "); recorded as 'error'");
            return RunResult.error(planned.set(), planned.run(), planned.periods(), plan.conditions());
        }
        if ("interrupted".equals(result.outcome())) {
            interrupted = true;
            return null;
        }
        return result;
    }

    private void checkMatchesPlan(RunResult r, int line) {
        String where = resultsFile() + " line " + line + " (set " + r.set() + " run " + r.run() + ")";
        if (r.set() > plan.sets().size()) {
            throw new ExperimentInputException(where + " has set " + r.set() + " but only " + plan.sets().size()
                    + " sets are planned; use the same --sets or another --out");
        }
        if (!plan.shard().includes(r.set(), r.run())) {
            throw new ExperimentInputException(where + " is not a run of shard " + plan.shard()
                    + "; use the same --shard or another --out");
        }
        PeriodSet planned = plan.sets().get(r.set() - 1);
        if (!planned.sameRunsAs(r.periods())) {
            throw new ExperimentInputException(where + " was made with periods " + r.periods().label()
                    + ", the planned set has " + planned.label() + "; use the same --sets or another --out");
        }
        RunConditions c = plan.conditions();
        RunConditions rc = r.conditions();
        long plannedSeed = c.seedOf(r.set(), r.run());
        long plannedRobot = c.robotSeedOf(r.set(), r.run());
        if (!c.scenario().equals(rc.scenario()) || c.timeScale() != rc.timeScale() || c.design() != rc.design()
                || !Objects.equals(c.cpuLimitCpus(), rc.cpuLimitCpus())
                || plannedSeed != r.worldSeed() || !Objects.equals(c.gridResolutionM(), rc.gridResolutionM())
                || plannedRobot != r.robotSeed()) {
            throw new ExperimentInputException(where + " was made with scenario " + rc.scenario() + ", time scale "
                    + rc.timeScale() + ", design " + rc.design().label() + ", seed " + r.worldSeed() + ", grid "
                    + gridLabel(rc.gridResolutionM()) + ", robot seed " + r.robotSeed() + ", CPU limit "
                    + cpuLabel(rc.cpuLimitCpus()) + "; now scenario " + c.scenario() + ", time scale " + c.timeScale()
                    + ", design " + c.design().label() + ", seed " + plannedSeed + ", grid " + gridLabel(c.gridResolutionM())
                    + ", robot seed " + plannedRobot + ", CPU limit " + cpuLabel(c.cpuLimitCpus())
                    + "; use the same options or another --out");
        }
    }

    private static String cpuLabel(Double cpus) {
        return cpus == null ? "none" : Decimals.plain(cpus) + (cpus == 1 ? " CPU" : " CPUs");
    }

    private static String gridLabel(Double m) {
        return m == null ? "default" : m + " m";
    }

    private static String lastLine(Path log) throws IOException {
        if (!Files.exists(log)) {
            return "(no output)";
        }
        List<String> lines = Files.readAllLines(log).stream().filter(l -> !l.isBlank()).toList();
        return lines.isEmpty() ? "(no output)" : lines.get(lines.size() - 1).strip();
    }

    private static void deleteRecursively(Path dir) throws IOException {
        if (!Files.exists(dir)) {
            return;
        }
        try (var paths = Files.walk(dir)) {
            for (Path p : paths.sorted(java.util.Comparator.reverseOrder()).toList()) {
                Files.delete(p);
            }
        }
    }
}
