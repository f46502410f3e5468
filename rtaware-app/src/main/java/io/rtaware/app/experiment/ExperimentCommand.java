package io.rtaware.app.experiment;

import io.rtaware.app.UserError;
import io.rtaware.app.cli.DurationConverter;
import io.rtaware.app.cli.TimeScaleConverter;
import io.rtaware.app.output.OutputFolder;
import io.rtaware.core.output.OutputWrites;
import io.rtaware.core.conditions.CpuQuota;
import io.rtaware.core.conditions.HostFiles;
import io.rtaware.core.conditions.HostReader;
import io.rtaware.experiment.ExperimentDesign;
import io.rtaware.experiment.ExperimentInputException;
import io.rtaware.experiment.ExperimentPlan;
import io.rtaware.experiment.ExperimentProfile;
import io.rtaware.experiment.ExperimentRunner;
import io.rtaware.experiment.ExperimentSets;
import io.rtaware.experiment.ExperimentSummary;
import io.rtaware.experiment.FolderLock;
import io.rtaware.experiment.JvmRunCommand;
import io.rtaware.experiment.MachineCheck;
import io.rtaware.experiment.QuietGate;
import io.rtaware.experiment.PeriodSet;
import io.rtaware.experiment.PlanFile;
import io.rtaware.experiment.ProgressBar;
import io.rtaware.experiment.ResultsCsv;
import io.rtaware.experiment.RunConditions;
import io.rtaware.experiment.RunResult;
import io.rtaware.experiment.Shard;
import io.rtaware.experiment.report.TerminalSummary;
import io.rtaware.sim.scenario.ScenarioLoader;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code rtaware experiment}: the paper's experiment. Each run is a fresh JVM running
 * {@code rtaware run}, one at a time, sets interleaved; every finished run is appended to
 * results.csv; the report (summary.json, report.md, report.html, figures) is written at the
 * end, or of what finished on Ctrl-C.
 */
@Command(name = "experiment", mixinStandardHelpOptions = true,
        description = {"Reproduce the paper's experiment: several sets of task periods, repeated runs of the course, "
                + "run time, distance to the finish, missed deadlines, and Welch t-tests between sets. Each run is a "
                + "fresh JVM running 'rtaware run'; runs of different sets are interleaved. Before each run the machine "
                + "is checked and, unless --allow-busy, the run waits for it to be quiet (at most --quiet-wait); the "
                + "report uses the quiet runs only unless --include-busy. Re-running into the same --out (or --resume) "
                + "skips the runs already in results.csv. Worst case it takes sets x runs x (360 s / time scale) plus "
                + "JVM start-up, plus the waits.",
                "Examples:",
                "  rtaware experiment --sets paper --runs 2 --time-scale 20 --out exp/quick",
                "  rtaware experiment --sets sweep-obstacle --runs 5 --shard 1/2 --out exp/a",
                "  rtaware experiment --sets my-sets.yaml --runs 10 --out experiments/mine"})
public final class ExperimentCommand implements Callable<Integer> {

    /** The run's time limit in world seconds (the paper's six minutes), for the worst-case ETA. */
    static final double RUN_LIMIT_S = 360;
    /** How long the machine is watched before each run to call it quiet or busy. */
    static final java.time.Duration CHECK_WINDOW = java.time.Duration.ofSeconds(2);

    @Option(names = "--sets", defaultValue = ExperimentSets.PAPER, paramLabel = "paper|sweep-obstacle|sweep-all|FILE",
            description = "'paper' (Table I: Sets 1-5), 'sweep-obstacle' (obstacle period 5 to 800 ms, the others 100 ms), "
                    + "'sweep-all' (all four at 5 to 800 ms) or a YAML file of sets or of a sweep "
                    + "(see docs/guide/experiment.md) (default: ${DEFAULT-VALUE}).")
    String sets;

    @Option(names = "--shard", paramLabel = "K/N", defaultValue = "1/1",
            description = "Make only share K of N of the planned runs (run j of set i when (i - 1 + j - 1) mod N = K - 1), "
                    + "with the seeds of the whole plan; merge the shards' folders with 'rtaware report DIR... --out DIR' "
                    + "(default: ${DEFAULT-VALUE}, all runs).")
    String shard;

    @Option(names = "--runs", defaultValue = "10", paramLabel = "N", description = "Runs per set (default: ${DEFAULT-VALUE}, as in the paper).")
    int runs;

    @Option(names = "--scenario", defaultValue = ScenarioLoader.PAPER_ROOM, paramLabel = "NAME|FILE",
            description = "The course, passed to 'rtaware run': a built-in scenario (" + ScenarioLoader.BUILT_IN_NAMES
                    + ") or a scenario YAML file (default: ${DEFAULT-VALUE}).")
    String scenario;

    @Option(names = "--time-scale", converter = TimeScaleConverter.class, defaultValue = "10", paramLabel = "K",
            description = "World time runs K times faster than wall time, emulating a computer K times slower "
                    + "(default: ${DEFAULT-VALUE}, the 'paper' profile with run's 0.05 m grid: see docs/paper-experiment.md; "
                    + "the report states it).")
    double timeScale;

    @Option(names = "--grid-resolution", paramLabel = "M",
            description = "Occupancy grid cell size in metres, passed to 'rtaware run' (default: run's own default).")
    Double gridResolutionM;

    @Option(names = "--seed", defaultValue = "1", paramLabel = "S",
            description = "World seed of set 1 run 1; the design gives the others (default: ${DEFAULT-VALUE}).")
    long seed;

    @Option(names = "--design", defaultValue = "independent", paramLabel = "independent|blocked",
            description = "'independent': every run its own world seed and a robot drawn from the population; 'blocked': "
                    + "run j of every set shares world seed S + j - 1 and robot j, to be analysed blocked on j (default: ${DEFAULT-VALUE}).")
    String design;

    @Option(names = "--robot-seed", paramLabel = "S", description = "First robot seed of the population (alone: every run "
            + "drives this one robot) (default: a population of robots 1 to " + RunConditions.POPULATION_ROBOTS + ").")
    Long robotSeed;

    @Option(names = "--robots", paramLabel = "N", description = "The population's size: robot seeds S to S + N - 1 "
            + "(default: 1 with --robot-seed, else " + RunConditions.POPULATION_ROBOTS + ").")
    Integer robots;

    @Option(names = "--cpu-limit", paramLabel = "CPUS", description = "Run each run's JVM (controller and built-in "
            + "server) under a CPU quota (e.g. 0.5; 'run --cpu-limit'; needs root), to emulate a smaller computer.")
    Double cpuLimit;

    @Option(names = "--out", paramLabel = "DIR", description = "Output folder (default: experiments/<timestamp>).")
    Path out;

    @Option(names = "--record",
            description = "Record each run to run.mcap in its folder (see rtaware run --record).")
    boolean record;

    @Option(names = "--allow-busy", description = "Do not wait for a quiet machine before each run; runs on a busy "
            + "machine are labelled in results.csv and left out of the report unless --include-busy; when not one "
            + "run was quiet, the report uses them all and is labelled busy.")
    boolean allowBusy;

    @Option(names = "--include-busy", description = "Use every run in the summary, tables, t-tests and claims, not only "
            + "those made on a quiet machine (the report says how many of each).")
    boolean includeBusy;

    @Option(names = "--quiet-wait", defaultValue = "600s", paramLabel = "DURATION", converter = DurationConverter.class,
            description = "Wait at most this long for a quiet machine before each run, then run it labelled busy "
                    + "(default: ${DEFAULT-VALUE}).")
    long quietWaitNs;

    @Option(names = "--resume", description = "Continue the experiment in --out with the plan stored there (sets, runs, "
            + "scenario, time scale, seed, grid), skipping the runs already in its results.csv.")
    boolean resume;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws IOException, InterruptedException {
        ExperimentPlan requested = resume ? null : plan();
        CpuQuota.refusal(cpuLimit).ifPresent(line -> {
            throw new UserError(line); // before the folder is made: exit 2, nothing written
        });
        OutputFolder folder = OutputFolder.of("--out", outputFolder());
        Path dir = folder.path();
        try (FolderLock lock = FolderLock.acquire(folder.create())) {
            ExperimentPlan plan = resume ? ResumedPlan.of(dir, spec.commandLine().getParseResult(), this::plan) : requested;
            return run(plan, dir);
        } catch (ExperimentInputException e) {
            throw new UserError(e.getMessage());
        } catch (IOException e) {
            System.err.println("rtaware: experiment in " + dir + ": could not write: " + e.getMessage()
                    + " (what finished is in " + dir.resolve(ResultsCsv.FILE_NAME) + ")");
            return OutputWrites.EXIT_WRITE_FAILED;
        }
    }

    private int run(ExperimentPlan plan, Path dir) throws IOException, InterruptedException {
        int runs = plan.runsPerSet();
        String scenario = plan.conditions().scenario();
        double timeScale = plan.conditions().timeScale();
        System.setProperty("java.awt.headless", "true");
        if (!Files.exists(dir.resolve(ExperimentProfile.FILE_NAME))) {
            ExperimentProfile.of(plan, ExperimentProfile.describeThisMachine()).write(dir);
        }
        ProgressBar progress = new ProgressBar(System.err, System.console() != null, System::nanoTime,
                RUN_LIMIT_S / timeScale);
        QuietGate gate = new QuietGate(MachineCheck.overWindow(new HostReader(HostFiles.system(), System::nanoTime),
                CHECK_WINDOW), s -> Thread.sleep((long) (s * 1000)), System::nanoTime, quietWaitNs / 1e9, allowBusy);
        ExperimentRunner runner = new ExperimentRunner(plan, JvmRunCommand.ofCurrentProcess(JvmRunCommand.RTAWARE_MAIN),
                dir, progress).recordEachRun(record).quietGate(gate);
        int total = plan.order().size();
        System.out.printf(Locale.ROOT, "rtaware experiment: %d set(s) x %d run(s) of %s at time scale x%s into %s%s; %s%n",
                plan.sets().size(), runs, scenario, timeScale, dir, plan.shard().whole() ? ""
                        : " (shard " + plan.shard() + ": " + total + " of " + plan.fullOrder().size() + " runs)",
                plan.conditions().robotsInWords());
        CountDownLatch reported = new CountDownLatch(1);
        Thread hook = new Thread(() -> {
            runner.interrupt();
            try {
                reported.await(2, TimeUnit.MINUTES);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "rtaware-experiment-stop");
        Runtime.getRuntime().addShutdownHook(hook);
        try {
            List<RunResult> rows = runner.run();
            if (runner.interrupted()) {
                System.err.println("interrupted: " + rows.size() + " of " + total + " runs are in "
                        + dir.resolve(ResultsCsv.FILE_NAME) + "; run the same command again (or --resume) to continue");
            }
            if (rows.isEmpty()) {
                return runner.interrupted() ? 130 : 0;
            }
            Optional<ExperimentSummary> summary = ReportRendering.render(dir, scenario, includeBusy, allowBusy,
                    System.err);
            summary.ifPresent(s -> TerminalSummary.print(s, dir, System.out));
            return runner.interrupted() ? 130 : summary.isPresent() ? 0 : OutputWrites.EXIT_WRITE_FAILED;
        } catch (ExperimentInputException e) {
            throw new UserError(e.getMessage());
        } finally {
            reported.countDown();
            try {
                Runtime.getRuntime().removeShutdownHook(hook);
            } catch (IllegalStateException shuttingDown) {
                // The hook is running: it returns now that the report is written.
            }
        }
    }

    /** @return the plan the options ask for */
    ExperimentPlan plan() {
        if (runs < 1 || runs > ExperimentPlan.MAX_RUNS_PER_SET) {
            throw new UserError("--runs must be in 1.." + ExperimentPlan.MAX_RUNS_PER_SET + ", got " + runs);
        }
        if (gridResolutionM != null && !(gridResolutionM > 0)) {
            throw new UserError("--grid-resolution must be a positive number of metres, got " + gridResolutionM);
        }
        ExperimentPlan plan;
        Shard share;
        try {
            List<PeriodSet> periodSets = ExperimentSets.resolve(sets);
            share = Shard.parse(shard);
            plan = new ExperimentPlan(periodSets, runs, RunConditions.ofPopulation(scenario, timeScale, seed, gridResolutionM,
                    robotSeed, robots, ExperimentDesign.parse(design)).withCpuLimit(cpuLimit), share);
        } catch (ExperimentInputException | IllegalArgumentException e) {
            throw new UserError(e.getMessage());
        }
        if (plan.order().isEmpty()) {
            throw new UserError("--shard " + share + " has no runs: the plan has only " + plan.fullOrder().size()
                    + " run(s); use fewer shards");
        }
        return plan;
    }

    private Path outputFolder() {
        if (resume) {
            if (out == null) {
                throw new UserError("--resume needs --out DIR, the folder of the experiment to continue");
            }
            if (!Files.exists(out.resolve(ResultsCsv.FILE_NAME)) && !Files.exists(out.resolve(PlanFile.FILE_NAME))) {
                throw new UserError("nothing to resume: " + out + " holds no " + PlanFile.FILE_NAME + " or "
                        + ResultsCsv.FILE_NAME);
            }
            return out;
        }
        if (out != null) {
            return out;
        }
        return Path.of("experiments", LocalDateTime.now().format(DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss")));
    }
}
