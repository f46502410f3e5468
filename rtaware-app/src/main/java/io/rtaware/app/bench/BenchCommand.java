package io.rtaware.app.bench;

import io.rtaware.app.UserError;
import io.rtaware.app.cli.CommandMonitor;
import io.rtaware.app.cli.DurationConverter;
import io.rtaware.app.cli.MemoryBudget;
import io.rtaware.app.cli.RecordOptions;
import io.rtaware.app.cli.TimeScaleConverter;
import io.rtaware.app.cli.TraceOptions;
import io.rtaware.app.foxglove.FoxgloveMixin;
import io.rtaware.app.live.LiveMixin;
import io.rtaware.app.output.OutputFile;
import io.rtaware.core.output.OutputWrites;
import io.rtaware.app.ros2.DdsMixin;
import io.rtaware.app.ros2.ExportMixin;
import io.rtaware.app.ros2.ExportOptions;
import io.rtaware.app.ros2.RosDistroMixin;
import io.rtaware.bench.compare.CompareReport;
import io.rtaware.bench.compare.CompareRun;
import io.rtaware.bench.compare.Goal;
import io.rtaware.bench.compare.PairedRounds;
import io.rtaware.bench.compare.ReleaseStats;
import io.rtaware.bench.compare.RunResult;
import io.rtaware.bench.compare.TaskSweep;
import io.rtaware.bench.load.BenchSpec;
import io.rtaware.bench.load.BenchTask;
import io.rtaware.bench.load.BusyWork;
import io.rtaware.bench.load.CpuLoad;
import io.rtaware.bench.load.GarbageLoad;
import io.rtaware.bench.load.LatenessHistogram;
import io.rtaware.core.analysis.ReportSections;
import io.rtaware.core.conditions.Conditions;
import io.rtaware.core.conditions.ConditionsMeter;
import io.rtaware.core.monitor.AdaptivePolicy;
import io.rtaware.core.monitor.ConsoleReporter;
import io.rtaware.core.monitor.ExecutorKind;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.monitor.ThreadSetup;
import io.rtaware.core.output.OutputFiles;
import io.rtaware.core.report.LatenessSpread;
import io.rtaware.core.report.Report;
import io.rtaware.core.report.ReportDocument;
import io.rtaware.core.report.SummaryTable;
import io.rtaware.core.report.TaskReport;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.testing.ThreadAllocation;
import io.rtaware.core.time.Clock;
import io.rtaware.core.time.Durations;
import io.rtaware.core.time.MonotonicSleeper;
import io.rtaware.core.time.SystemClock;
import io.rtaware.core.trace.TraceRecorder;
import io.rtaware.foxglove.FoxgloveServer;
import io.rtaware.live.LiveAddressException;
import io.rtaware.live.LiveView;
import io.rtaware.record.RecordingPlan;
import io.rtaware.record.RecordingStats;
import io.rtaware.record.RunRecorder;
import io.rtaware.ros2.export.MonitorExporter;
import io.rtaware.ros2.graph.Ros2Distro;
import io.rtaware.rt.ClockNanosleep;
import io.rtaware.rt.CpuLatencyRequest;
import io.rtaware.rt.MinimalTimerSlack;
import io.rtaware.rt.RealtimeThreads;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.Callable;
import java.util.function.Supplier;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code rtaware bench}: runs a synthetic task set on the real threaded executor and prints the
 * termination summary, so a user sees how this machine copes with N tasks of a given period and
 * CPU work.
 */
@Command(name = "bench", mixinStandardHelpOptions = true,
        description = {"Run a synthetic task set and report misses, lateness and execution times. Work is real CPU "
                + "work (a busy loop calibrated at start-up), not sleep.",
                "Examples:",
                "  rtaware bench --tasks 4 --period 10ms --work 2ms --duration 10s --json r.json",
                "  rtaware bench --spec \"a:10ms:2ms,b:50ms:20ms\" --chain --trace trace.json",
                "  rtaware bench --spec \"a:10ms:2ms,b:2ms..50ms:1ms\" --chain --adaptive",
                "  rtaware bench --tasks 2 --period 1ms --work 100us --realtime",
                "  rtaware bench --compare --tasks 8 --period 10ms --work 1ms --json c.json",
                "",
                "  rtaware bench --executor pooled --tasks 10000 --period 10ms --work 0",
                "  rtaware bench --sweep-tasks 10,100,1000,10000 --period 10ms --duration 4s",
                "",
                "--compare runs the same task set on rtaware (threaded and pooled executors), on "
                + "ScheduledThreadPoolExecutor (one thread per task, and one pool of --workers threads), on a bare "
                + "parkNanos loop (the floor for a Java thread) and on the timer wheels of Netty and Agrona "
                + "(netty-wheel, agrona-wheel), interleaved in segments so all of them see the same machine noise, and "
                + "prints lateness, misses, bursts, CPU and bytes allocated per release side by side "
                + "(JSON schema rtaware.bench-compare/1 with --json)."})
public final class BenchCommand implements Callable<Integer> {

    /** Exit status when the run ended before its duration (a task hit a fatal VM error). */
    public static final int EXIT_ENDED_EARLY = 1;
    /** The report section with the spread of the tasks' p99 lateness ({@link LatenessSpread}). */
    static final String LATENESS_SPREAD_SECTION = "lateness_spread";

    /** Exit status of {@code --fail-on-alloc} when the framework allocated in steady state. */
    public static final int EXIT_ALLOCATED = 4;

    /** Most tasks the warm-up runs (enough to compile every path of a cycle, few enough to fit beside the set). */
    static final int WARM_UP_TASKS = 1000;
    /** The warm-up's task that overruns now and then (not in the measured run). */
    static final String WARM_UP_OVERRUN_TASK = "warm-up-overrun";

    @Option(names = "--tasks", paramLabel = "N", description = "Number of identical tasks (default: ${DEFAULT-VALUE}).", defaultValue = "4")
    int tasks;

    @Option(names = "--period", converter = DurationConverter.class, paramLabel = "DURATION", defaultValue = "10ms",
            description = "Period of each task, e.g. 10ms (default: ${DEFAULT-VALUE}).")
    long periodNs;

    @Option(names = "--work", converter = DurationConverter.class, paramLabel = "DURATION", defaultValue = "2ms",
            description = "CPU work per cycle, e.g. 2ms; 0 for none (default: ${DEFAULT-VALUE}).")
    long workNs;

    @Option(names = "--spec", paramLabel = "NAME:PERIOD:WORK,...", description = "A mixed task set, each task as name:period:work, for example "
            + "a:10ms:2ms,b:50ms:20ms (overrides --tasks, --period and --work).")
    String spec;

    @Option(names = "--chain", description = "Each task consumes the previous task's output key.")
    boolean chain;

    @Option(names = "--stagger", description = "Spread the tasks' first releases evenly over their period (task i "
            + "of n first released at i/n of it) instead of releasing every task at the same instant; on every "
            + "executor, with --compare and --sweep-tasks too.")
    boolean stagger;

    @Option(names = "--warmup", converter = DurationConverter.class, paramLabel = "DURATION", defaultValue = "2s",
            description = "Before the measured run, run up to " + WARM_UP_TASKS + " of the tasks on the same "
                    + "executor for this long, with the same live console, plus one task that overruns now and "
                    + "then, and discard the numbers: the JIT compiles the cycle's code, a missed deadline's "
                    + "too, and the collector settles after the monitor's allocation; 0 for none (default: "
                    + "${DEFAULT-VALUE}). --compare and --sweep-tasks warm up with a round of their own.")
    long warmUpNs;

    @Option(names = "--duration", converter = DurationConverter.class, paramLabel = "DURATION", defaultValue = "10s",
            description = "How long to run, in world time (default: ${DEFAULT-VALUE}).")
    long durationNs;

    @Option(names = "--time-scale", converter = TimeScaleConverter.class, defaultValue = "1", paramLabel = "K", description = "World time runs K times faster than wall time (default: ${DEFAULT-VALUE}).")
    double timeScale;

    @Option(names = "--json", description = "Write the JSON report (schema rtaware.report/1) to FILE.", paramLabel = "FILE")
    Path json;

    @Option(names = "--quiet", description = "Do not print live miss reports.")
    boolean quiet;

    @Option(names = "--fail-on-alloc", description = "Exit with status 4 if the framework's threads (tasks and "
            + "watchdog) allocated any byte in the steady state (the last two thirds of the run).")
    boolean failOnAlloc;

    @Option(names = "--compare", description = "Run the task set on rtaware (threaded, pooled), ScheduledThreadPoolExecutor "
            + "(per task, pooled), a bare parkNanos loop and the timer wheels of Netty (netty-wheel) and Agrona "
            + "(agrona-wheel), interleaved, and compare them; --duration is the measured time per executor.")
    boolean compare;

    @Option(names = "--segment", converter = DurationConverter.class, paramLabel = "DURATION", defaultValue = "2s",
            description = "With --compare: length of one executor's turn (default: ${DEFAULT-VALUE}).")
    long segmentNs;

    @Option(names = "--load", paramLabel = "N", defaultValue = "0",
            description = "Start N busy threads competing for the cores (default: ${DEFAULT-VALUE}).")
    int loadThreads;

    @Option(names = "--gc-pressure", paramLabel = "MBps", defaultValue = "0",
            description = "Allocate short- and medium-lived garbage at MBps megabytes per second on a "
                    + "helper thread (default: ${DEFAULT-VALUE}).")
    double gcPressureMbps;

    @Mixin
    TraceOptions trace;

    @Mixin
    RecordOptions record;

    @Option(names = "--adaptive",
            description = "Move the period of tasks declared with a range of periods in --spec, for example "
                    + "a:5ms..50ms:1ms, from run-time evidence.")
    boolean adaptive;

    @Option(names = "--realtime",
            description = "SCHED_FIFO task threads in rate-monotonic order, 1 ns timer slack, and the CPUs held out of "
                    + "deep idle for the run through /dev/cpu_dma_latency, as cyclictest does (Linux, root or CAP_SYS_NICE).")
    boolean realtime;

    @Option(names = "--kernel-timer-slack",
            description = "Leave the task threads and workers the kernel's timer slack (50 us by default on Linux) "
                    + "instead of asking for 1 ns, to compare; the slack they had is in the conditions (timer_slack_ns).")
    boolean kernelTimerSlack;

    @Option(names = "--rt-priority", paramLabel = "P", defaultValue = "80",
            description = "SCHED_FIFO priority of the shortest-period task with --realtime (default: ${DEFAULT-VALUE}).")
    int rtPriority;

    @Option(names = "--affinity", paramLabel = "TASK=CPU,...", split = ",",
            description = "With --realtime, pin task threads to CPUs, e.g. a=1,b=0.")
    Map<String, Integer> affinity = new LinkedHashMap<>();

    @Option(names = "--executor", paramLabel = "threaded|pooled",
            description = "Executor of the periodic tasks: threaded (a thread per task) or pooled (--workers "
                    + "threads, earliest deadline first). With --compare: compare only that family, or the rows "
                    + "named, e.g. rtaware-pooled,netty-wheel,agrona-wheel (default: threaded for a run, every row "
                    + "for --compare).")
    String executor;

    @Option(names = "--sleep", paramLabel = "nanosleep|park",
            description = "How the threaded executor's task threads sleep until their next release: "
                    + "nanosleep (clock_nanosleep to the absolute release time, one system call; the default "
                    + "where libc can be bound, else park) or park (parkNanos of "
                    + "LockSupport, as a plain Java thread does). With --compare it applies to rtaware's row; the park-loop row always parks.")
    String sleep = "nanosleep";

    @Option(names = "--workers", paramLabel = "N",
            description = "Worker threads of the pooled executors (default: the number of cores).")
    Integer workers;

    @Option(names = "--sweep-tasks", paramLabel = "N,N,...", split = ",",
            description = "Run one comparison (as --compare) per task count, e.g. 10,100,1000,10000, print misses "
                    + "and the p99 and p99.9 lateness per executor and count, and plot them (--plot).")
    List<Integer> sweepTasks;

    @Option(names = "--plot", paramLabel = "FILE", defaultValue = "bench-sweep.png",
            description = "With --sweep-tasks: the PNG to write (default: ${DEFAULT-VALUE}).")
    Path plot;

    @Option(names = "--lateness-histogram", paramLabel = "FILE",
            description = "Write every cycle's release lateness in 1 us buckets (cyclictest's histogram format).")
    Path latenessHistogram;

    @Mixin
    LiveMixin live;

    @Mixin
    FoxgloveMixin foxglove;

    @Mixin
    ExportMixin export;

    @Mixin
    RosDistroMixin rosDistro;

    @Mixin
    DdsMixin dds;

    private final Supplier<MemoryBudget> memory;

    /** The command with this JVM's heap as its memory budget. */
    public BenchCommand() {
        this(MemoryBudget::ofThisJvm);
    }

    /** @param memory the heap the task set and the trace may take, asked for when the command runs */
    public BenchCommand(Supplier<MemoryBudget> memory) {
        this.memory = memory;
    }

    @Override
    public Integer call() throws IOException, InterruptedException {
        List<BenchSpec> specs = taskSet();
        live.options(); // a bad --live-port or --live-bind ends the command before anything runs
        foxglove.address(); // so does a bad --foxglove
        exportOptions(); // so does a bad --ros-distro, --dds or --export option
        if (json != null) {
            OutputFile.of("--json", json);
        }
        trace.checkOutput();
        record.checkOutput();
        // A comparison (and each count of a sweep) keeps a monitor and the comparison's own
        // per-task lateness histogram at once.
        boolean comparing = compare || sweepTasks != null;
        int taskCount = sweepTasks == null || sweepTasks.isEmpty() ? specs.size()
                : sweepTasks.stream().filter(n -> n != null).mapToInt(Integer::intValue).max().orElse(specs.size());
        long perTaskBytes = Monitor.estimatedHeapBytesPerTask() + (comparing ? ReleaseStats.estimatedHeapBytes() : 0);
        // A single run's warm-up monitor is built while the measured one already exists.
        int warmUpTasks = comparing || warmUpNs <= 0 ? 0 : Math.min(taskCount, WARM_UP_TASKS);
        memory.get().require(MemoryBudget.times(taskCount + warmUpTasks, perTaskBytes), taskCount + " task(s) ("
                + perTaskBytes / 1024 + " KB of " + (comparing ? "monitor and comparison" : "monitor")
                + " bookkeeping per task" + (warmUpTasks > 0 ? ", plus " + warmUpTasks + " for the warm-up" : "") + ")");
        memory.get().require(MemoryBudget.add(MemoryBudget.times(taskCount, perTaskBytes), trace.heapBytes()),
                trace.describe() + " with " + taskCount + " task(s)");
        if (durationNs <= 0) {
            throw new UserError("--duration must be positive, got " + Durations.format(durationNs));
        }
        if (loadThreads < 0) {
            throw new UserError("--load must be 0 or more, got " + loadThreads);
        }
        if (!(gcPressureMbps >= 0) || Double.isInfinite(gcPressureMbps)) {
            throw new UserError("--gc-pressure must be 0 or more MB/s, got " + gcPressureMbps);
        }
        if (sweepTasks != null) {
            if (sweepTasks.isEmpty() || sweepTasks.stream().anyMatch(n -> n == null || n < 1)) {
                throw new UserError("--sweep-tasks needs task counts of at least 1, got " + sweepTasks);
            }
            OutputFile.of("--plot", plot); // before the sweep runs: an empty name, a folder, a socket, ...
            compare = true;
        }
        if (compare && (spec != null || chain || timeScale != 1.0 || live.options().enabled() || record.enabled()
                || foxglove.enabled() || export.requested())) {
            // --export needs one monitor to watch; a comparison runs several executors in turn
            throw new UserError((sweepTasks != null ? "--sweep-tasks" : "--compare") + " takes --tasks, --period and"
                    + " --work (not --spec, --chain, --time-scale, --live, --record, --foxglove or --export)");
        }
        if (compare && segmentNs < 2 * specs.stream().mapToLong(BenchSpec::periodNs).max().orElse(0)) {
            throw new UserError("--segment must be at least two periods, got " + Durations.format(segmentNs));
        }
        if (executor != null && !executor.equals("threaded") && !executor.equals("pooled")) {
            if (!compare) {
                throw new UserError("--executor must be threaded or pooled, got " + executor);
            }
            compareRows(); // a comparison's rows by their labels: a bad one ends the command here
        }
        if (workers != null && (workers < 1 || workers > Math.min(taskCount, ExecutorKind.Pooled.maxWorkers()))) {
            // a worker runs one task at a time; past 16 per core a pool is a thread per task (ExecutorKind.Pooled)
            throw new UserError("--workers must be 1 to " + Math.min(taskCount, ExecutorKind.Pooled.maxWorkers())
                    + " (at most one per task, " + taskCount + " here, and " + ExecutorKind.Pooled.MAX_WORKERS_PER_CORE
                    + " per core, " + Runtime.getRuntime().availableProcessors() + " cores here), got " + workers);
        }
        if (!sleep.equals("nanosleep") && !sleep.equals("park")) {
            throw new UserError("--sleep must be nanosleep or park, got " + sleep);
        }
        sleeper = sleep.equals("park") ? null : ClockNanosleep.load().orElse(null);
        if (sleep.equals("nanosleep") && sleeper == null) {
            System.err.println("rtaware bench: clock_nanosleep cannot be bound here (not Linux, or no JNA); "
                    + "task threads park");
        }
        BusyWork work = BusyWork.calibrate();
        try (CpuLoad load = CpuLoad.start(loadThreads); GarbageLoad garbage = GarbageLoad.start(gcPressureMbps)) {
            if (sweepTasks != null) {
                return sweep(work);
            }
            return compare ? compare(specs, work) : bench(specs, work);
        }
    }

    /** @return the rows --executor asks a comparison for: a family, or row labels such as netty-wheel,agrona-wheel */
    private List<String> compareRows() {
        if (executor == null || executor.equals("threaded") || executor.equals("pooled")) {
            return (executor == null ? CompareRun.Family.ALL : executor.equals("pooled") ? CompareRun.Family.POOLED
                    : CompareRun.Family.THREADED).rows();
        }
        try {
            return CompareRun.rows(executor);
        } catch (IllegalArgumentException e) {
            throw new UserError("--executor: " + e.getMessage());
        }
    }

    private int sweep(BusyWork work) throws IOException, InterruptedException {
        PrintStream out = System.out;
        List<Integer> counts = sweepTasks.stream().sorted().distinct().toList();
        ConditionsMeter.Span span = ConditionsMeter.ofThisProcess().start(1.0, "none");
        java.time.Instant started = java.time.Instant.now();
        TaskSweep sweep = new TaskSweep().run(counts, TaskSweep.comparison(n -> uniform(n), work, durationNs,
                segmentNs, System.err, compareRows(), workerCount(), sleeper, comparedThreadSetup()), System.err);
        Conditions measured = span.finish(periodNs / 1e6);
        out.printf(Locale.ROOT, "sweep: period %s, work %s, %s measured per executor and count; %s, %s%n",
                Durations.format(periodNs), Durations.format(workNs), Durations.format(durationNs),
                System.getProperty("java.vm.version"), CompareRun.collectors());
        out.print(sweep.table());
        OutputWrites writes = new OutputWrites(System.err);
        if (writes.writeFile(plot, OutputFiles.png(sweep.plot("period " + Durations.format(periodNs) + ", work "
                + Durations.format(workNs) + ", " + Runtime.getRuntime().availableProcessors() + " cores",
                TaskSweep.caption(measured, started))))) {
            out.println("plot written to " + plot);
        }
        return writes.exitStatus(0);
    }

    /** rtaware's rows ask for the smallest timer slack, as a run does, unless --kernel-timer-slack. */
    private ThreadSetup comparedThreadSetup() {
        return kernelTimerSlack ? null : MinimalTimerSlack.load().orElse(null);
    }

    private int compare(List<BenchSpec> specs, BusyWork work) throws IOException, InterruptedException {
        PrintStream out = System.out;
        CompareRun run = new CompareRun(specs, work, durationNs, segmentNs, System.err, compareRows(), workerCount(),
                sleeper, comparedThreadSetup());
        if (run.rows().isEmpty()) {
            throw new UserError("--compare: " + String.join(", ", run.leftOut()) + " need a thread per task, and "
                    + specs.size() + " tasks are too many for this machine's cores; choose a pooled row");
        }
        ConditionsMeter.Span span = ConditionsMeter.ofThisProcess().start(1.0, "none");
        List<RunResult> runs = run.run();
        Conditions measured = span.finish(specs.stream().mapToLong(BenchSpec::periodNs).min().orElse(0) / 1e6);
        CompareReport report = new CompareReport(CompareReport.SCHEMA, specs.size(), specs.get(0).periodNs() / 1e6,
                specs.get(0).workNs() / 1e6, run.measuredNs() / 1e9, segmentNs / 1e9, loadThreads, gcPressureMbps,
                System.getProperty("java.vm.version"), CompareRun.collectors(), runs, Goal.check(runs),
                PairedRounds.check(runs), measured);
        out.print(report.table());
        out.println(measured.summaryLine());
        OutputWrites writes = new OutputWrites(System.err);
        if (json != null && writes.writeFile(json, report::write)) {
            out.println("comparison written to " + json);
        }
        return writes.exitStatus(0);
    }

    private int bench(List<BenchSpec> specs, BusyWork work) throws IOException, InterruptedException {
        PrintStream out = System.out;
        Clock clock = Clock.forTimeScale(timeScale);

        if (rtPriority < 2 || rtPriority > 99) {
            throw new UserError("--rt-priority must be 2..99, got " + rtPriority);
        }
        for (String task : affinity.keySet()) {
            if (specs.stream().noneMatch(s -> s.name().equals(task))) {
                throw new UserError("--affinity names task '" + task + "' but there is none; tasks: "
                        + String.join(", ", specs.stream().map(BenchSpec::name).toList()));
            }
        }
        Monitor.Builder builder = tasks(Monitor.builder(clock), specs, work);
        if (realtime) {
            builder.threadSetup(RealtimeThreads.configure(rtPriority, affinity, System.err));
        } else if (!kernelTimerSlack) {
            MinimalTimerSlack.load().ifPresent(builder::threadSetup);
        }
        LatenessHistogram histogram = null;
        if (latenessHistogram != null) {
            histogram = new LatenessHistogram();
            builder.listener(histogram);
        }
        Monitor monitor = CommandMonitor.build(builder);
        if (realtime) {
            // Held until the monitor's termination, which every way out of the run passes.
            CpuLatencyRequest.hold(CpuLatencyRequest.DEVICE, 0, System.err)
                    .ifPresent(request -> monitor.onTermination(report -> request.close()));
        }
        ConsoleReporter console = CommandMonitor.console(monitor, quiet, System.err);
        TraceRecorder recorder = trace.attach(monitor);
        RecordingPlan recordingPlan = new RecordingPlan().metadata("command", "bench")
                .metadata("tasks", String.join(",", specs.stream().map(s -> s.name() + ":" + Durations.format(s.periodNs())
                        + ":" + Durations.format(s.workNs())).toList()));
        if (timeScale != 1.0) {
            recordingPlan.clock(RecordingPlan.CLOCK_PERIOD_NS); // simulated time: /clock, for consumers that follow it
        }
        FoxgloveServer foxgloveServer = foxglove.start("bench", out, System.err);
        RunRecorder recording;
        try {
            recording = record.attach(monitor, recordingPlan.tap(foxgloveServer));
        } catch (RuntimeException e) {
            FoxgloveMixin.close(foxgloveServer);
            throw e;
        }
        out.printf("rtaware bench: %d task(s)%s for %s of world time (time scale x%s)%n", specs.size(),
                chain ? " in a chain" : "", Durations.format(durationNs), timeScale);
        LiveView liveView;
        try {
            liveView = LiveView.start(live.options(), monitor, out);
        } catch (LiveAddressException e) {
            throw new UserError(e.getMessage());
        }
        CommandMonitor.showMachine(liveView, monitor, () -> conditions);
        MonitorExporter exporter = exportOptions().map(e -> e.start(monitor, List.of(), List.of(), System.err))
                .orElse(null);
        Thread hook = monitor.installShutdownHook();
        OutputWrites writes = new OutputWrites(System.err);
        monitor.onTermination(writes.guarding("finish the run's report",
                report -> finish(monitor, report, console, recorder, recording, foxgloveServer, out, writes)));
        monitor.onTermination(report -> liveView.finish(report, null));
        warmUp(specs, work);
        ThreadAllocation.prepare();
        conditions = ConditionsMeter.ofThisProcess().start(timeScale, realtime
                ? "--realtime: SCHED_FIFO priority " + rtPriority + (affinity.isEmpty() ? "" : ", affinity " + affinity)
                + ", CPU latency request 0 us" : "none").timerSlackOf(monitor.timerSlack());
        monitor.onTasksStopped(conditions::end); // the report's building and its garbage are not the run's
        monitor.start();
        long wallNs = clock.toWallNanos(durationNs);
        // Steady state: the last two thirds of the run (the first third warms up the JIT).
        long untilSteadyNs = wallNs / 3;
        boolean endedEarly = monitor.awaitTermination(java.time.Duration.ofNanos(untilSteadyNs));
        ThreadAllocation allocation = endedEarly ? null : ThreadAllocation.ofFrameworkThreads();
        long releasesBefore = monitor.totalReleases();
        endedEarly |= monitor.awaitTermination(java.time.Duration.ofNanos(wallNs - untilSteadyNs));
        long allocatedBytes = endedEarly ? -1 : allocation.allocatedSince();
        String allocatingThreads = allocatedBytes > 0 ? allocation.allocatingThreads() : ""; // while they live
        long releases = monitor.totalReleases() - releasesBefore;
        CommandMonitor.stop(monitor, hook);
        liveView.close();
        FoxgloveMixin.close(foxgloveServer);
        if (histogram != null) {
            histogram.write(latenessHistogram);
        }
        ExportOptions.stop(exporter, System.err);
        if (endedEarly) {
            System.err.println("rtaware: the run ended before its duration (a task hit a fatal error, see above)");
            return EXIT_ENDED_EARLY;
        }
        out.printf(Locale.ROOT, "steady state (last 2/3 of the run): %d bytes allocated on %d framework thread(s)"
                        + " (task threads or pool workers, watchdog, the pool's statistics recorder)"
                        + " over %d releases = %.2f B/release%n", allocatedBytes,
                allocation.threads(), releases, releases == 0 ? 0.0 : (double) allocatedBytes / releases);
        if (failOnAlloc && allocatedBytes != 0) {
            System.err.println("rtaware: --fail-on-alloc: the framework allocated " + allocatedBytes
                    + " bytes in steady state (" + allocatingThreads + ")");
            return EXIT_ALLOCATED;
        }
        return writes.exitStatus(0);
    }

    /** Adds the bench tasks to a builder, on the chosen executor, with adaptive periods if asked. */
    private Monitor.Builder tasks(Monitor.Builder builder, List<BenchSpec> specs, BusyWork work) {
        builder.executor(executorKind()).sleeper(sleeper);
        if (adaptive) {
            builder.adaptivePeriods(AdaptivePolicy.defaults());
        }
        String previous = null;
        for (BenchSpec s : specs) {
            builder.task(s.name(), s.schedule(), new BenchTask(s.name(), s.workNs(), chain ? previous : null, work));
            previous = s.name();
        }
        return builder;
    }

    /**
     * Runs the first {@link #WARM_UP_TASKS} tasks (all, if fewer) on a monitor of their own for
     * {@code --warmup} of wall time and drops it; called with the measured monitor built, just
     * before its start. A run's first second otherwise measures the interpreter and the JIT
     * compiling the cycle, and, with thousands of tasks, a collector still cycling after the
     * monitor's allocation (ZGC's allocation-rate rule started a cycle every 200 ms for 1.5 s
     * after 10 000 tasks were built; most misses of a 20 s pooled run fell in that time, issue 16).
     */
    private void warmUp(List<BenchSpec> specs, BusyWork work) throws InterruptedException {
        if (warmUpNs <= 0) {
            return;
        }
        List<BenchSpec> subset = specs.subList(0, Math.min(specs.size(), WARM_UP_TASKS));
        System.err.printf(Locale.ROOT, "rtaware bench: warm-up, %d task(s) and one that overruns now and then, for %s"
                + " (not counted)%n", subset.size(), Durations.format(warmUpNs));
        Monitor.Builder builder = tasks(Monitor.builder(new SystemClock()), subset, work);
        // One more task, of the shortest period, overruns by a period and a half every 50th cycle:
        // the paths of a miss and of skipped releases are compiled before the measured run meets
        // them (compiled without them, the first miss threw the cycle's code away).
        long shortestNs = subset.stream().mapToLong(BenchSpec::periodNs).min().orElse(10_000_000L);
        builder.task(WARM_UP_OVERRUN_TASK, Schedule.periodic(java.time.Duration.ofNanos(shortestNs)),
                BenchTask.overrunning(WARM_UP_OVERRUN_TASK, 0, shortestNs + shortestNs / 2, 50, work));
        if (latenessHistogram != null) {
            builder.listener(new LatenessHistogram());
        }
        Monitor warmUp = CommandMonitor.build(builder);
        // The listeners the measured run will have, of the same classes: a cycle calls each, and
        // code the JIT compiled for none is thrown away at the measured run's first cycles (the
        // first periods of 10 000 tasks then ran interpreted and missed). Their output is dropped.
        ConsoleReporter console = CommandMonitor.console(warmUp, quiet,
                new PrintStream(OutputStream.nullOutputStream(), false, StandardCharsets.UTF_8));
        warmUp.start();
        warmUp.awaitTermination(java.time.Duration.ofNanos(warmUpNs));
        warmUp.stop();
        if (console != null) {
            console.close();
        }
    }

    /** The measurement of the run's conditions, from just before the monitor's start (null before). */
    private volatile ConditionsMeter.Span conditions;

    /** The sleeper {@code --sleep} chose (null: park), set when the command starts. */
    private MonotonicSleeper sleeper;

    private int workerCount() {
        return workers != null ? workers : Runtime.getRuntime().availableProcessors();
    }

    private ExecutorKind executorKind() {
        return "pooled".equals(executor)
                ? ExecutorKind.pooled(workerCount(), ExecutorKind.PoolOrder.EARLIEST_DEADLINE_FIRST)
                : ExecutorKind.threaded();
    }

    private void finish(Monitor monitor, Report report, ConsoleReporter console, TraceRecorder recorder,
                        RunRecorder recording, FoxgloveServer foxgloveServer, PrintStream out, OutputWrites writes) {
        if (console != null) {
            console.close();
        }
        out.println();
        out.print(SummaryTable.format(report));
        ReportDocument doc = new ReportDocument(report);
        // With one task the line would repeat its row of the table.
        LatenessSpread.of(report).filter(spread -> spread.tasks() > 1).ifPresent(spread -> {
            out.println();
            out.println(spread.line());
            doc.section(LATENESS_SPREAD_SECTION, spread);
        });
        ConditionsMeter.Span span = conditions;
        Conditions measured = null;
        if (span != null) {
            measured = span.finish(report.tasks().stream().map(TaskReport::periodMs).filter(p -> p != null && p > 0)
                    .mapToDouble(Double::doubleValue).min().orElse(Double.NaN));
            doc.section(Conditions.SECTION, measured);
            out.println();
            out.println(measured.summaryLine());
            if (recording != null) {
                recording.closingMetadata(Conditions.MCAP_METADATA, ConditionsMeter.metadata(measured));
            }
        }
        out.println();
        out.print(ReportSections.enrich(doc, Runtime.getRuntime().availableProcessors()).text());
        String history = ReportSections.addPeriodHistory(doc, monitor);
        if (!history.isEmpty()) {
            out.println();
            out.print(history);
        }
        trace.write(recorder, out, writes);
        RecordingStats stats = RecordOptions.finish(recording, out, writes);
        if (stats != null) {
            doc.section("recording", stats);
        }
        if (foxgloveServer != null) {
            doc.section(FoxgloveMixin.SECTION, foxgloveServer.stats()); // after the recorder's last message
        }
        if (json != null && writes.writeFile(json, doc::write)) {
            out.println("report written to " + json);
        }
    }

    private List<BenchSpec> taskSet() {
        if (spec != null) {
            List<BenchSpec> parsed;
            try {
                parsed = BenchSpec.parseList(spec);
            } catch (IllegalArgumentException e) {
                throw new UserError(e.getMessage());
            }
            return stagger ? BenchSpec.staggered(parsed) : parsed;
        }
        if (tasks < 1) {
            throw new UserError("--tasks must be at least 1, got " + tasks);
        }
        return uniform(tasks);
    }

    /** @return {@code count} tasks t1..tN of --period and --work, staggered with --stagger */
    private List<BenchSpec> uniform(int count) {
        List<BenchSpec> specs = new ArrayList<>();
        try {
            for (int i = 1; i <= count; i++) {
                specs.add(BenchSpec.of("t" + i, periodNs, workNs));
            }
        } catch (IllegalArgumentException e) {
            throw new UserError(e.getMessage());
        }
        return stagger ? BenchSpec.staggered(specs) : specs;
    }

    /**
     * @return the export options when {@code --export} was given
     * @throws io.rtaware.app.UserError for a bad --export, --ros-distro or --dds option
     */
    private Optional<ExportOptions> exportOptions() {
        Ros2Distro distro = rosDistro.distro(export.requested(), "--export");
        return export.options(distro, dds.settings(export.requested(), "--export", environmentDomain(), distro));
    }

    /** @return ROS_DOMAIN_ID, else 0: bench has no --domain */
    private static int environmentDomain() {
        String id = System.getenv("ROS_DOMAIN_ID");
        try {
            return id == null || id.isBlank() ? 0 : Integer.parseInt(id.trim());
        } catch (NumberFormatException e) {
            throw new io.rtaware.app.UserError("ROS_DOMAIN_ID must be a number 0..232, got '" + id + "'");
        }
    }
}
