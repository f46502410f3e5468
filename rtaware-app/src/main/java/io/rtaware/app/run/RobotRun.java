package io.rtaware.app.run;

import io.rtaware.app.UserError;
import io.rtaware.app.cli.CommandMonitor;
import io.rtaware.app.cli.RecordOptions;
import io.rtaware.app.foxglove.FoxgloveMixin;
import io.rtaware.app.ros2.ExportOptions;
import io.rtaware.app.ros2.Ros2Options;
import io.rtaware.app.ros2.Ros2Wiring;
import io.rtaware.core.conditions.Conditions;
import io.rtaware.core.conditions.ConditionsMeter;
import io.rtaware.core.monitor.ConsoleReporter;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.monitor.TaskCounters;
import io.rtaware.core.monitor.TaskInfo;
import io.rtaware.core.report.Report;
import io.rtaware.core.report.TaskReport;
import io.rtaware.core.time.Clock;
import io.rtaware.core.trace.TraceRecorder;
import io.rtaware.foxglove.FoxgloveServer;
import io.rtaware.live.LiveAddressException;
import io.rtaware.live.LiveView;
import io.rtaware.live.RunScene;
import io.rtaware.record.RunRecorder;
import io.rtaware.robot.msg.CourseStatus;
import io.rtaware.robotrun.CourseCheck;
import io.rtaware.robotrun.NavRun;
import io.rtaware.robotrun.Referee;
import io.rtaware.robotrun.RobotLink;
import io.rtaware.robotrun.RunOutcome;
import io.rtaware.robotrun.RunSection;
import io.rtaware.robotrun.RunState;
import io.rtaware.ros2.export.MonitorExporter;
import io.rtaware.ros2msg.RobotTopics;
import io.rtaware.rt.CpuLatencyRequest;
import io.rtaware.rt.MinimalTimerSlack;
import io.rtaware.rt.RealtimeThreads;
import io.rtaware.sim.map.OccupancyMap;
import io.rtaware.sim.scenario.Scenario;
import io.rtaware.sim.scenario.ScenarioException;
import io.rtaware.sim.scenario.ScenarioLoader;
import io.rtaware.sim.server.PlayerSimServer;
import io.rtaware.sim.server.ServerConfig;
import io.rtaware.sim.server.SimCommandSupport;
import io.rtaware.sim.world.RobotModel;
import java.io.IOException;
import java.io.PrintStream;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;

/**
 * {@code rtaware run}'s wiring of one robot run of the paper's course ({@link NavRun}, the library
 * entry point, does the run): opens the robot ({@link RobotLink}: the built-in simulator on a free
 * loopback port, an external Player server, or a ROS 2 robot), adds what the options ask for to
 * the run's monitor (real-time threads, the console, the trace, the recording, the live view,
 * Foxglove, the ROS 2 export), prints the status while the run goes, and on every way out
 * (finish, time limit, stuck, Ctrl-C, a crash, a lost connection, data that cannot be true)
 * stops the robot first and then writes the report.
 */
public final class RobotRun {

    private final RunOptions options;
    /** {@code --ros2}: a ROS 2 robot over Zenoh instead of a Player server. */
    private final Optional<Ros2Options> ros2;
    /** {@code --export}: keys and health published over ROS 2. */
    private final Optional<ExportOptions> export;
    private final PrintStream out;
    private final PrintStream err;
    private RecordOptions record = new RecordOptions();
    private FoxgloveMixin foxglove = new FoxgloveMixin();

    /**
     * @param options what to run
     * @param out where the summary goes
     * @param err where live status and miss lines go
     */
    public RobotRun(RunOptions options, PrintStream out, PrintStream err) {
        this(options, Optional.empty(), Optional.empty(), out, err);
    }

    /**
     * @param options what to run
     * @param ros2 the ROS 2 robot to drive instead of a Player server, if any
     * @param export where to export keys and health over ROS 2, if anywhere
     * @param out where the summary goes
     * @param err where live status and miss lines go
     */
    public RobotRun(RunOptions options, Optional<Ros2Options> ros2, Optional<ExportOptions> export, PrintStream out,
                    PrintStream err) {
        this.options = options;
        this.ros2 = ros2;
        this.export = export;
        this.out = out;
        this.err = err;
    }

    /**
     * @param recording the {@code --record} option
     * @return this run
     */
    public RobotRun recording(RecordOptions recording) {
        this.record = recording;
        return this;
    }

    /**
     * @param server the {@code --foxglove} option
     * @return this run
     */
    public RobotRun foxglove(FoxgloveMixin server) {
        this.foxglove = server;
        return this;
    }

    /**
     * Runs to the end.
     *
     * @return the exit status: 0 for a finished run (completed, timeout, stuck), 1 for an error,
     *     130 if interrupted
     * @throws UserError for a bad scenario or an unreachable server
     * @throws IOException if the simulator cannot start or the report cannot be written
     */
    public int execute() throws IOException {
        Scenario scenario = loadScenario();
        CourseCheck.warnings(scenario).forEach(w -> err.println("rtaware run: warning: " + w + "; running anyway"));
        RobotModel model = robotModel(scenario);
        Clock clock = Clock.forTimeScale(options.timeScale());
        if (ros2.isPresent() && !options.builtInSimulator()) {
            throw new UserError("--ros2 and --player exclude each other (a ROS 2 robot is reached with --zenoh or --dds)");
        }
        boolean simulated = options.builtInSimulator() && ros2.map(Ros2Options::builtInSimulator).orElse(true);
        if (simulated && scenario.map().isEmpty()) {
            throw new UserError("scenario '" + scenario.name() + "' has no map; the built-in simulator needs one (or use --player HOST:PORT)");
        }
        try (RobotLink link = openLink(scenario, model, clock, simulated)) {
            return runOn(scenario, model, clock, link);
        }
    }

    /** The robot: the built-in simulator (over Player, or as a ROS 2 robot), an external Player server, or a ROS 2 robot. */
    private RobotLink openLink(Scenario scenario, RobotModel model, Clock clock, boolean simulated) throws IOException {
        PlayerSimServer server = simulated ? SimCommandSupport.start(scenario, model, clock, ServerConfig.defaults(0),
                options.seed(), options.robotSeed()) : null;
        try {
            if (ros2.isPresent()) {
                return RobotLink.ros2(Ros2Wiring.link(ros2.get(), server), server);
            }
            return server != null ? RobotLink.simulator(server) : RobotLink.player(options.playerHost(), options.playerPort());
        } catch (IOException e) {
            throw new UserError(e.getMessage()); // an external Player server that cannot be reached at the start
        } catch (RuntimeException e) {
            if (server != null) {
                server.close();
            }
            throw e;
        }
    }

    /**
     * The robot model: {@code --robot} if given (keeping the scenario's overrides when it names
     * the same model), else the scenario's {@code robot:} section, else the Koala; then
     * {@code --top-speed} if given.
     */
    private RobotModel robotModel(Scenario scenario) {
        RobotModel base = scenario.robot().orElse(null);
        String name = options.robot() != null ? options.robot() : base != null ? base.name() : RobotModel.KOALA_NAME;
        try {
            RobotModel model = base != null && base.name().equals(name) ? base
                    : RobotModel.named(name, RobotModel.PAPER_TOP_SPEED_MPS);
            return options.topSpeedMps() == null ? model : model.withTopSpeed(options.topSpeedMps());
        } catch (IllegalArgumentException e) {
            throw new UserError(e.getMessage());
        }
    }

    private Scenario loadScenario() {
        try {
            return ScenarioLoader.load(options.scenario());
        } catch (ScenarioException e) {
            throw new UserError(e.getMessage());
        }
    }

    private NavRun.Settings settings() {
        return new NavRun.Settings(options.periods().nanosByTask(), options.timeScale(), options.seed(),
                options.robotSeed(), options.gridResolutionM(), options.inflationMarginM(), options.stuckAfterS(),
                options.modelName());
    }

    private int runOn(Scenario scenario, RobotModel model, Clock clock, RobotLink link) throws IOException {
        NavRun run;
        try {
            run = new NavRun(scenario, model, settings(), link, clock);
        } catch (IllegalArgumentException e) {
            throw new UserError(e.getMessage());
        }
        Monitor.Builder builder = run.monitorBuilder();
        if (options.realtime()) {
            builder.threadSetup(RealtimeThreads.configure(RealtimeThreads.DEFAULT_TOP_PRIORITY, Map.of(), err));
        } else if (!options.kernelTimerSlack()) {
            MinimalTimerSlack.load().ifPresent(builder::threadSetup);
        }
        Monitor monitor = CommandMonitor.build(builder);
        if (options.realtime()) {
            // Held until the monitor's termination, which every way out of the run passes.
            CpuLatencyRequest.hold(CpuLatencyRequest.DEVICE, 0, err)
                    .ifPresent(request -> monitor.onTermination(report -> request.close()));
        }
        MonitorExporter exporter = export.map(e -> e.start(monitor, run.exportedKeys(), RobotTopics.STATIC_TRANSFORMS, err))
                .orElse(null);
        ConsoleReporter console = CommandMonitor.console(monitor, options.quiet(), err);
        TraceRecorder trace = options.trace().attach(monitor);
        FoxgloveServer foxgloveServer = foxglove.start("run", out, err);
        RunRecorder recorder;
        try {
            recorder = record.attach(monitor, run.recordingPlan().metadata("command", "run").tap(foxgloveServer));
        } catch (RuntimeException e) {
            FoxgloveMixin.close(foxgloveServer);
            throw e;
        }

        // Everything the termination handler reads exists before the start: Ctrl-C may run it on
        // the shutdown-hook thread at any moment from here on.
        RunArtifacts artifacts = new RunArtifacts(options, scenario, run.navConfig(), out, err);
        ConditionsMeter.Span conditions = ConditionsMeter.ofThisProcess().start(options.timeScale(), options.realtime()
                ? "--realtime: SCHED_FIFO from priority " + RealtimeThreads.DEFAULT_TOP_PRIORITY + ", CPU latency request 0 us"
                : "none").timerSlackOf(monitor.timerSlack());
        monitor.onTasksStopped(conditions::end); // the report's building and its garbage are not the run's
        LiveView live;
        try {
            live = LiveView.start(options.live(), monitor, new RunScene(scenario.name(),
                    scenario.map().map(OccupancyMap::toGrid).orElse(null), scenario.waypoints(),
                    run.controller().keys(), run.controller()::mediatorCounts, () -> outcomeName(run.state())), out);
        } catch (LiveAddressException e) {
            throw new UserError(e.getMessage());
        }
        CommandMonitor.showMachine(live, monitor, () -> conditions);
        run.attach(monitor, recorder); // connects the ground truth before the start: its first sample is the start
        monitor.onTermination(artifacts.writes().guarding("finish the run's report", report -> {
            if (console != null) {
                console.close();
            }
            RunSection section = run.finish(); // stops the referee, whose last sample the recorder still takes
            Conditions measured = conditions.finish(shortestPeriodMs(report));
            artifacts.section(Conditions.SECTION, measured);
            if (recorder != null) {
                recorder.closingMetadata(Conditions.MCAP_METADATA, ConditionsMeter.metadata(measured));
            }
            artifacts.section("recording", RecordOptions.finish(recorder, out, artifacts.writes()));
            if (foxgloveServer != null) {
                artifacts.section(FoxgloveMixin.SECTION, foxgloveServer.stats()); // after the recorder's last message
            }
            live.finish(report, section);
            link.ros2().ifPresent(r -> artifacts.section("ros2", r.section()));
            artifacts.write(report, section, run.playerSection(), run.referee(),
                    run.controller().finalMap().orElse(null), scenario.map().orElse(null));
            options.trace().write(trace, out, artifacts.writes());
        }));
        Thread hook = monitor.installShutdownHook();

        monitor.start();
        run.started();
        Referee referee = run.referee();
        live.truePose(referee::latest, referee.kind());
        if (!options.quiet()) {
            err.printf(Locale.ROOT, "rtaware run: scenario %s, periods %s, time scale x%s, robot %s, ground truth from %s%n",
                    scenario.name(), options.periods(), trim(options.timeScale()), link.describe(model), referee.kind());
        }

        supervise(run, monitor, referee, link.dataTaskName());
        CommandMonitor.stop(monitor, hook);
        live.close();
        FoxgloveMixin.close(foxgloveServer);
        ExportOptions.stop(exporter, err);
        if (!options.quiet()) {
            link.ros2().ifPresent(r -> err.println(r.summary()));
        }
        return artifacts.exitStatus(run.state().ending().outcome().exitStatus());
    }

    /** Runs the supervision with a status line (on a terminal every 250 ms, else every 5 s) and says how the run ended. */
    private void supervise(NavRun run, Monitor monitor, Referee referee, String dataTask) {
        boolean tty = System.console() != null;
        CourseStatus course = new CourseStatus();
        long[] lastStatusWallNs = {System.nanoTime()};
        RunState.Ending ending = run.superviseUntilEnd(elapsedS -> {
            if (!options.quiet() && System.nanoTime() - lastStatusWallNs[0] >= (tty ? 250_000_000L : 5_000_000_000L)) {
                lastStatusWallNs[0] = System.nanoTime();
                printStatus(monitor, dataTask, run.readCourse(course), elapsedS, referee, tty);
            }
        });
        if (ending == null) {
            return; // Ctrl-C, SIGTERM or a STOP_ALL error: the termination handler records the outcome.
        }
        if (!options.quiet()) {
            printStatus(monitor, dataTask, run.readCourse(course),
                    (monitor.clock().nanos() - run.state().startNs()) / 1e9, referee, tty);
            err.println();
        }
        if (!options.quiet() || ending.outcome() == RunOutcome.ERROR) {
            err.println("rtaware run: " + ending.outcome().jsonName() + ": " + ending.reason() + "; stopping the robot");
        }
    }

    /**
     * @param report a finished run
     * @return the shortest period of its periodic tasks, ms, or NaN when it has none
     */
    static double shortestPeriodMs(Report report) {
        return report.tasks().stream().map(TaskReport::periodMs).filter(p -> p != null && p > 0)
                .mapToDouble(Double::doubleValue).min().orElse(Double.NaN);
    }

    private static String outcomeName(RunState state) {
        RunOutcome outcome = state.outcome();
        return outcome == null ? null : outcome.jsonName();
    }

    private void printStatus(Monitor monitor, String dataTask, CourseStatus course, double elapsedS, Referee referee,
                             boolean tty) {
        StringBuilder misses = new StringBuilder();
        for (TaskInfo task : monitor.tasks()) {
            if (task.name().equals(dataTask)) {
                continue;
            }
            TaskCounters c = monitor.counters(task.index());
            misses.append(misses.length() == 0 ? "" : " ").append(task.name()).append('=').append(c.misses());
        }
        // Both distances are the controller's own, straight lines from its odometry pose: the
        // true distances are in the report (distance_to_finish_m, waypoint_passes[]).
        String line = String.format(Locale.ROOT,
                "t=%6.1fs  waypoint %d of %d %5.2f m away, finish %5.2f m (straight, by odometry)  %5.1f m driven  misses: %s",
                elapsedS, Math.min(course.waypointsReached + 1, course.waypointsTotal), course.waypointsTotal,
                course.distanceToGoalM, course.distanceToFinishM, referee.travelledM(), misses);
        if (tty) {
            err.print("\r" + line + "   ");
        } else {
            err.println(line);
        }
        err.flush();
    }

    private static String trim(double v) {
        return v == Math.rint(v) ? Long.toString((long) v) : Double.toString(v);
    }
}
