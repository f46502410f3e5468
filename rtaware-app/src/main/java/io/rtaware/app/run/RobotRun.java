package io.rtaware.app.run;

import io.rtaware.app.UserError;
import io.rtaware.app.cli.CommandMonitor;
import io.rtaware.app.cli.RecordOptions;
import io.rtaware.app.foxglove.FoxgloveMixin;
import io.rtaware.foxglove.FoxgloveServer;
import io.rtaware.live.LiveAddressException;
import io.rtaware.live.LiveView;
import io.rtaware.live.RunScene;
import io.rtaware.app.ros2.ExportOptions;
import io.rtaware.app.ros2.Ros2Link;
import io.rtaware.app.ros2.Ros2Options;
import io.rtaware.core.conditions.Conditions;
import io.rtaware.core.conditions.ConditionsMeter;
import io.rtaware.core.monitor.ConsoleReporter;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.monitor.TaskCounters;
import io.rtaware.core.monitor.TaskInfo;
import io.rtaware.core.report.Report;
import io.rtaware.core.report.Rounding;
import io.rtaware.core.report.TaskReport;
import io.rtaware.core.task.ErrorPolicy;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.Clock;
import io.rtaware.core.trace.TraceRecorder;
import io.rtaware.record.RunRecorder;
import io.rtaware.rt.CpuLatencyRequest;
import io.rtaware.rt.RealtimeThreads;
import io.rtaware.nav.NavConfig;
import io.rtaware.nav.NavController;
import io.rtaware.player.client.PlayerClient;
import io.rtaware.ros2.export.MonitorExporter;
import io.rtaware.player.client.PlayerClientOptions;
import io.rtaware.player.client.PlayerCounters;
import io.rtaware.player.client.PlayerStats;
import io.rtaware.player.task.DeviceSamples;
import io.rtaware.player.task.PlayerConfig;
import io.rtaware.player.task.PlayerDataTask;
import io.rtaware.robot.geometry.Point2d;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.robot.msg.CourseStatus;
import io.rtaware.robot.msg.OccupancyGrid;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.robot.msg.RobotKeys;
import io.rtaware.robot.msg.VelocityCommand;
import io.rtaware.sim.map.OccupancyMap;
import io.rtaware.sim.scenario.Scenario;
import io.rtaware.sim.scenario.ScenarioException;
import io.rtaware.sim.scenario.ScenarioLoader;
import io.rtaware.sim.server.PlayerSimServer;
import io.rtaware.sim.server.ServerConfig;
import io.rtaware.sim.server.SimCommandSupport;
import io.rtaware.sim.world.LaserConfig;
import io.rtaware.sim.world.RobotModel;
import io.rtaware.sim.world.World;
import java.io.IOException;
import java.io.PrintStream;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.locks.LockSupport;
import java.util.function.Supplier;

/**
 * One robot run of the paper's course: the composition root of {@code rtaware run}. Starts the
 * built-in simulator on a free loopback port (or uses an external Player server), wires the
 * Player data task and the navigation behaviors onto one monitor, watches the run from outside
 * (ground truth, progress, time limit, safety faults; see {@link Supervisor}), and on every way
 * out (finish, time limit, stuck, Ctrl-C, a crash, a lost connection, data that cannot be true)
 * stops the robot first and then writes the report.
 */
public final class RobotRun {

    /** Task name of the Player data task in reports. */
    public static final String PLAYER_TASK = "player";
    private static final long SAMPLE_PERIOD_NS = 100_000_000L;

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

        PlayerSimServer server = null;
        BuiltInSimulatorLog simulatorLog = null;
        String host = options.playerHost();
        int port = options.playerPort();
        if (ros2.isPresent() && !options.builtInSimulator()) {
            throw new UserError("--ros2 and --player exclude each other (a ROS 2 robot is reached with --zenoh or --dds)");
        }
        boolean externalRos2 = ros2.isPresent() && !ros2.get().builtInSimulator();
        if (options.builtInSimulator() && !externalRos2) {
            if (scenario.map().isEmpty()) {
                throw new UserError("scenario '" + scenario.name() + "' has no map; the built-in simulator needs one (or use --player HOST:PORT)");
            }
            simulatorLog = BuiltInSimulatorLog.install(err);
            server = SimCommandSupport.start(scenario, model, clock, ServerConfig.defaults(0), options.seed(),
                    options.robotSeed());
            host = ServerConfig.LOOPBACK;
            port = server.port();
        } else if (!externalRos2) {
            checkReachable(host, port);
        }
        Ros2Link link = null;
        try {
            if (ros2.isPresent()) {
                link = Ros2Link.open(ros2.get(), server);
            }
            return runAgainst(scenario, model, clock, host, port, server, link);
        } finally {
            if (link != null) {
                link.close();
            }
            if (server != null) {
                server.close();
            }
            if (simulatorLog != null) {
                simulatorLog.close();
            }
        }
    }

    /**
     * The data task reconnects with back-off once running; a server that cannot be reached at the
     * start is the user's mistake (a wrong address or a server not started) and ends the command.
     */
    private static void checkReachable(String host, int port) {
        try (PlayerClient probe = PlayerClient.connect(host, port, PlayerClientOptions.defaults(), new PlayerCounters())) {
            probe.serverVersion();
        } catch (IOException e) {
            throw new UserError(e.getMessage());
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

    private int runAgainst(Scenario scenario, RobotModel model, Clock clock, String host, int port,
                           PlayerSimServer server, Ros2Link link) throws IOException {
        NavConfig navConfig = navConfig(scenario, model);
        NavController nav = new NavController(navConfig);
        PlayerDataTask player = link != null ? null
                : new PlayerDataTask(PlayerConfig.of(host, port).withReconnect(true, 500, 8000));
        TaskSpec dataTask = link != null ? link.taskSpec()
                : new TaskSpec(PLAYER_TASK, Schedule.continuous(), ErrorPolicy.CONTINUE, player);
        Supplier<String> safetyFault = player != null ? player::fault : link.task()::fault;

        Monitor.Builder builder = Monitor.builder(clock).task(dataTask);
        nav.taskSpecs().forEach(builder::task);
        if (options.realtime()) {
            builder.threadSetup(RealtimeThreads.configure(RealtimeThreads.DEFAULT_TOP_PRIORITY, Map.of(), err));
        }
        Monitor monitor = CommandMonitor.build(builder);
        if (options.realtime()) {
            // Held until the monitor's termination, which every way out of the run passes.
            CpuLatencyRequest.hold(CpuLatencyRequest.DEVICE, 0, err)
                    .ifPresent(request -> monitor.onTermination(report -> request.close()));
        }
        MonitorExporter exporter = export.map(e -> e.start(monitor, RunExports.keys(nav), RunExports.STATIC_TRANSFORMS, err)).orElse(null);
        ConsoleReporter console = CommandMonitor.console(monitor, options.quiet(), err);
        TraceRecorder trace = options.trace().attach(monitor);
        FoxgloveServer foxgloveServer = foxglove.start("run", out, err);
        RunRecorder recorder;
        try {
            recorder = record.attach(monitor, RunRecording.plan(scenario, options, navConfig, model.name(), server)
                    .tap(foxgloveServer));
        } catch (RuntimeException e) {
            FoxgloveMixin.close(foxgloveServer);
            throw e;
        }

        // Everything the termination handler reads exists before the start: Ctrl-C may run it on
        // the shutdown-hook thread at any moment from here on.
        RunState state = new RunState(clock.nanos());
        CourseStatus course = new CourseStatus();
        List<RunSection.WaypointPass> passes = new CopyOnWriteArrayList<>();
        PlayerSimServer simulator = server;
        Supplier<Pose2d> truthNow = simulator != null ? () -> simulator.withWorld(World::pose)
                : () -> state.referee() == null ? null : state.referee().latest();
        RunArtifacts artifacts = new RunArtifacts(options, scenario, navConfig, out, err);
        ConditionsMeter.Span conditions = ConditionsMeter.ofThisProcess().start(options.timeScale(), options.realtime()
                ? "--realtime: SCHED_FIFO from priority " + RealtimeThreads.DEFAULT_TOP_PRIORITY + ", CPU latency request 0 us"
                : "none");
        LiveView live;
        try {
            live = LiveView.start(options.live(), monitor, new RunScene(scenario.name(),
                    scenario.map().map(RobotRun::worldGrid).orElse(null),
                    scenario.waypoints(), nav.keys(), nav::mediatorCounts, () -> outcomeName(state)), out);
        } catch (LiveAddressException e) {
            throw new UserError(e.getMessage());
        }
        CommandMonitor.showMachine(live, monitor, () -> conditions);
        // Connected before the start, so the first ground-truth sample is the pose at the start.
        Referee.PoseSource truthSource = poseSource(host, port, clock, monitor);
        Referee.PoseSource truth = RunRecording.recordingGroundTruth(truthSource, recorder, clock);
        monitor.onTermination(report -> {
            try {
                if (console != null) {
                    console.close();
                }
                state.end(RunOutcome.INTERRUPTED, "interrupted (Ctrl-C or SIGTERM)", clock.nanos());
                Referee referee = state.referee();
                if (referee != null) {
                    referee.close(); // closes the pose source too
                } else {
                    closeQuietly(truth); // stopped before the start: no referee owns the source yet
                }
                Conditions measured = conditions.finish(shortestPeriodMs(report));
                artifacts.section(Conditions.SECTION, measured);
                if (recorder != null) {
                    recorder.closingMetadata(Conditions.MCAP_METADATA, ConditionsMeter.metadata(measured));
                }
                artifacts.section("recording", RecordOptions.finish(recorder, out, artifacts.writes()));
                if (foxgloveServer != null) {
                    artifacts.section(FoxgloveMixin.SECTION, foxgloveServer.stats()); // after the recorder's last message
                }
                monitor.read(nav.keys().course(), course);
                long collisions = server != null ? server.withWorld(World::contactCount) : state.stallEdges();
                Map<String, Object> robotErrors = server != null ? server.withWorld(w -> w.odometryBias().parameters())
                        : null;
                double[] safety = server != null
                        ? server.withWorld(w -> new double[] {w.minClearanceM(), w.nearMisses()}) : null;
                RunSection run = runSection(scenario, nav, course, referee, state.ending(),
                        state.elapsedNs(clock.nanos()), collisions, server != null, List.copyOf(passes), model,
                        robotErrors, safety);
                live.finish(report, run);
                if (link != null) {
                    artifacts.section("ros2", link.section());
                }
                artifacts.write(report, run, player == null ? null : playerSection(player, host, port, truthSource), referee,
                        nav.finalMap().orElse(null), scenario.map().orElse(null));
                options.trace().write(trace, out, artifacts.writes());
            } catch (RuntimeException | Error e) {
                // Whatever failed, the run must not end with status 0 as if its report were complete.
                artifacts.writes().failed("finish the run's report", e);
            }
        });
        Thread hook = monitor.installShutdownHook();

        monitor.start();
        long startNs = clock.nanos();
        Odometry believed = new Odometry();
        Referee referee = new Referee(clock, startNs, SAMPLE_PERIOD_NS, truth, () -> totalMisses(monitor),
                () -> monitor.read(RobotKeys.ODOMETRY, believed) == 0 ? null : believed.pose()).start();
        MonitorView view = new MonitorView(monitor, nav, referee, safetyFault);
        Supervisor supervisor = new Supervisor(view, clock, System::nanoTime,
                startNs, scenario.timeLimitS(), options.stuckAfterS());
        state.started(startNs, referee, supervisor);
        live.truePose(referee::latest, referee.kind());
        if (!options.quiet()) {
            String robot = link != null ? link.describe() : host + ":" + port + " ("
                    + (server != null ? "built-in simulator, " + model.describe() : "external Player server") + ")";
            err.printf(Locale.ROOT, "rtaware run: scenario %s, periods %s, time scale x%s, robot %s, ground truth from %s%n",
                    scenario.name(), options.periods(), trim(options.timeScale()), robot, referee.kind());
        }

        supervise(scenario, clock, startNs, monitor, nav, referee, supervisor, view, course, state, truthNow, passes,
                new SafetyLog(recorder, server));
        CommandMonitor.stop(monitor, hook);
        live.close();
        FoxgloveMixin.close(foxgloveServer);
        ExportOptions.stop(exporter, err);
        if (link != null && !options.quiet()) {
            err.println(link.summary());
        }
        return artifacts.exitStatus(state.ending().outcome().exitStatus());
    }

    /**
     * @param report a finished run
     * @return the shortest period of its periodic tasks, ms, or NaN when it has none
     */
    static double shortestPeriodMs(Report report) {
        return report.tasks().stream().map(TaskReport::periodMs).filter(p -> p != null && p > 0)
                .mapToDouble(Double::doubleValue).min().orElse(Double.NaN);
    }

    private static void closeQuietly(Referee.PoseSource source) {
        try {
            source.close();
        } catch (Exception ignored) {
            // the run is over; a failing close of the observer's connection changes nothing
        }
    }

    /**
     * @param map the scenario's map
     * @return the same walls as an occupancy grid for the live view (and {@code sim --foxglove}'s
     *     {@code /map}): obstacles occupied, the rest free
     */
    public static OccupancyGrid worldGrid(OccupancyMap map) {
        OccupancyGrid grid = new OccupancyGrid(map.widthCells() * map.heightCells());
        grid.setGeometry(map.widthCells(), map.heightCells(), map.resolutionM(), map.originXM(), map.originYM());
        for (int row = 0; row < map.heightCells(); row++) {
            for (int col = 0; col < map.widthCells(); col++) {
                grid.cells[row * map.widthCells() + col] = map.isObstacle(col, row) ? OccupancyGrid.OCCUPIED : OccupancyGrid.FREE;
            }
        }
        return grid;
    }

    private static String outcomeName(RunState state) {
        RunOutcome outcome = state.outcome();
        return outcome == null ? null : outcome.jsonName();
    }

    private static long totalMisses(Monitor monitor) {
        long sum = 0;
        for (int i = 0; i < monitor.tasks().size(); i++) {
            sum += monitor.counters(i).misses();
        }
        return sum;
    }

    /** The supervisor's view of a running monitor: the keys' newest values, the referee, the data task's fault. */
    private static final class MonitorView implements Supervisor.View {
        private final Monitor monitor;
        private final NavController nav;
        private final Referee referee;
        private final Supplier<String> safetyFault;
        private final CourseStatus course = new CourseStatus();
        private final Odometry odometry = new Odometry();
        private final VelocityCommand motor = new VelocityCommand();
        private long odometryGeneration;

        MonitorView(Monitor monitor, NavController nav, Referee referee, Supplier<String> safetyFault) {
            this.monitor = monitor;
            this.nav = nav;
            this.referee = referee;
            this.safetyFault = safetyFault;
        }

        @Override
        public void refresh() {
            monitor.read(nav.keys().course(), course);
            odometryGeneration = monitor.read(RobotKeys.ODOMETRY, odometry);
            monitor.read(RobotKeys.MOTOR, motor);
        }

        @Override
        public boolean courseDone() {
            return course.done;
        }

        @Override
        public long odometryGeneration() {
            return odometryGeneration;
        }

        @Override
        public boolean stalled() {
            return odometry.stall;
        }

        @Override
        public boolean commandedToMove() {
            return !motor.isStop();
        }

        @Override
        public double displacementOverLastM(double windowS) {
            return referee.displacementOverLastM(windowS);
        }

        @Override
        public String safetyFault() {
            return safetyFault.get();
        }

        /** @return the course status read at the last refresh */
        CourseStatus course() {
            return course;
        }

        /** @return the odometry read at the last refresh */
        Odometry odometry() {
            return odometry;
        }
    }

    /** Watches the run until it ends; records the ending. Returns when the run is over. */
    private void supervise(Scenario scenario, Clock clock, long startNs, Monitor monitor, NavController nav,
                           Referee referee, Supervisor supervisor, MonitorView view, CourseStatus course,
                           RunState state, Supplier<Pose2d> truthNow, List<RunSection.WaypointPass> passes,
                           SafetyLog safety) {
        long pollWallNs = Math.max(1_000_000L, Math.min(50_000_000L, (long) (50_000_000L / options.timeScale())));
        long lastStatusWallNs = System.nanoTime();
        boolean tty = System.console() != null;
        while (true) {
            LockSupport.parkNanos(pollWallNs);
            if (monitor.isStopping()) {
                return; // Ctrl-C, SIGTERM or a STOP_ALL error: the termination handler records the outcome.
            }
            double elapsedS = (clock.nanos() - startNs) / 1e9;
            RunState.Ending ending = supervisor.check();
            recordPasses(scenario, view.course(), view.odometry(), truthNow, elapsedS, passes);
            safety.poll(clock.nanos());
            if (ending != null) {
                safety.ended(ending, clock.nanos());
                state.end(ending.outcome(), ending.reason(), clock.nanos());
                if (!options.quiet()) {
                    monitor.read(nav.keys().course(), course);
                    printStatus(monitor, nav, course, elapsedS, referee, tty);
                    err.println();
                }
                if (!options.quiet() || ending.outcome() == RunOutcome.ERROR) {
                    err.println("rtaware run: " + ending.outcome().jsonName() + ": " + ending.reason()
                            + "; stopping the robot");
                }
                return;
            }
            if (!options.quiet() && System.nanoTime() - lastStatusWallNs >= (tty ? 250_000_000L : 5_000_000_000L)) {
                lastStatusWallNs = System.nanoTime();
                monitor.read(nav.keys().course(), course);
                printStatus(monitor, nav, course, elapsedS, referee, tty);
            }
        }
    }

    /**
     * Records each waypoint the controller has newly counted as passed, with the true and the
     * believed distance from it at this moment (polled, so up to one poll late).
     */
    private static void recordPasses(Scenario scenario, CourseStatus course, Odometry odometry,
                                     Supplier<Pose2d> truthNow, double elapsedS, List<RunSection.WaypointPass> passes) {
        int reached = Math.min(course.waypointsReached, scenario.waypoints().size());
        if (reached <= passes.size()) {
            return;
        }
        Pose2d truth = truthNow.get();
        for (int i = passes.size(); i < reached; i++) {
            Point2d wp = scenario.waypoints().get(i);
            double trueM = truth == null ? Double.NaN : truth.position().distanceTo(wp);
            double believedM = odometry.pose().position().distanceTo(wp);
            passes.add(new RunSection.WaypointPass(i, round3(elapsedS), round3(trueM), round3(believedM)));
        }
    }

    private void printStatus(Monitor monitor, NavController nav, CourseStatus course, double elapsedS,
                             Referee referee, boolean tty) {
        StringBuilder misses = new StringBuilder();
        for (TaskInfo task : monitor.tasks()) {
            if (task.name().equals(PLAYER_TASK) || task.name().equals(Ros2Link.TASK)) {
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

    private NavConfig navConfig(Scenario scenario, RobotModel model) {
        NavConfig.Builder b = NavConfig.builder()
                .topSpeedMps(model.topSpeedMps())
                .inflationMarginM(options.inflationMarginM())
                .reactionLimits(model.stoppingDistanceM(model.topSpeedMps()), model.laserDelayNs(LaserConfig.URG_04LX))
                .laserMinRangeM(LaserConfig.URG_04LX.minRangeM())
                .obstacleSpeedMps(scenario.fastestActorMps())
                .periodsNs(options.periods().nanosByTask())
                .goalToleranceM(scenario.goalToleranceM())
                .waypoints(scenario.waypoints());
        OccupancyMap map = scenario.map().orElse(null);
        double margin = 1.0;
        if (map != null) {
            b.grid(options.gridResolutionM(), map.originXM() - margin, map.originYM() - margin,
                    map.widthM() + 2 * margin, map.heightM() + 2 * margin);
        } else {
            Pose2d s = scenario.start();
            b.grid(options.gridResolutionM(), s.xM() - 10, s.yM() - 10, 20, 20);
        }
        try {
            return b.build();
        } catch (IllegalArgumentException e) {
            throw new UserError(e.getMessage());
        }
    }

    /** Ground truth through Player's simulation:0 when the server has it, odometry otherwise. */
    private Referee.PoseSource poseSource(String host, int port, Clock clock, Monitor monitor) {
        if (host == null) {
            return odometrySource(monitor);
        }
        try {
            return GroundTruthSource.open(host, port, options.modelName(), clock);
        } catch (IOException e) {
            // No second connection or no simulation:0: fall back to odometry below.
        }
        return odometrySource(monitor);
    }

    private static Referee.PoseSource odometrySource(Monitor monitor) {
        Odometry odometry = new Odometry();
        return new Referee.PoseSource() {
            @Override
            public Pose2d pose() {
                return monitor.read(RobotKeys.ODOMETRY, odometry) == 0 ? null : odometry.pose();
            }

            @Override
            public String kind() {
                return "odometry";
            }
        };
    }

    private static PlayerSection playerSection(PlayerDataTask player, String host, int port, Referee.PoseSource truth) {
        PlayerStats stats = player.stats();
        Map<String, DeviceSamples> devices = new LinkedHashMap<>(player.deviceSamples());
        if (truth instanceof GroundTruthSource groundTruth) {
            devices.put("simulation:0", groundTruth.samples());
        }
        return new PlayerSection(host + ":" + port, player.serverVersion(), stats.connects(), stats.connectionLosses(),
                stats.protocolErrors(), devices, player.fault());
    }

    private RunSection runSection(Scenario scenario, NavController nav, CourseStatus course,
                                  Referee referee, RunState.Ending ending, long elapsedNs, long collisions,
                                  boolean simulator, List<RunSection.WaypointPass> passes, RobotModel model,
                                  Map<String, Object> robotErrors, double[] safety) {
        double runTimeS = elapsedNs / 1e9;
        List<GroundTruthGap> gaps = referee == null ? List.of() : referee.gaps(runTimeS);
        double uncoveredS = 0;
        boolean staleAtEnd = referee == null;
        for (GroundTruthGap gap : gaps) {
            uncoveredS += gap.toS() - gap.fromS();
            staleAtEnd |= gap.open();
        }
        Pose2d last = referee == null ? null : referee.latest();
        Point2d finish = scenario.finish();
        // A final pose older than the end of the run is not measured: no distance rather than a stale one.
        Double toFinish = last == null || staleAtEnd ? null : round3(last.position().distanceTo(finish));
        var counts = nav.mediatorCounts();
        Map<String, Long> mediator = new LinkedHashMap<>();
        mediator.put("obstacle", counts.obstacle());
        mediator.put("waypoint", counts.waypoint());
        mediator.put("stop", counts.stop());
        return new RunSection(scenario.name(), options.periods().millis(), ending.outcome().jsonName(),
                ending.outcome() == RunOutcome.COMPLETED, round3(runTimeS), course.waypointsReached,
                course.waypointsTotal, toFinish, round3(referee == null ? 0 : referee.travelledM()), collisions,
                mediator, referee == null ? "odometry" : referee.kind(), simulator ? "simulator" : "stall",
                options.timeScale(), options.seed(), options.gridResolutionM(), counts.staleStops(), ending.reason(),
                gaps, round3(Math.max(0, runTimeS - uncoveredS)), RunSection.COMPLETED_MEANS, passes,
                robotModelSection(model, simulator), options.inflationMarginM(),
                simulator ? options.robotSeed() : null, robotErrors, safety == null ? null : round3(safety[0]),
                safety == null ? null : (long) safety[1], safety == null ? null : World.NEAR_MISS_MARGIN_M,
                safety == null ? null : World.CLEARANCE_LIMIT_M);
    }

    private static Map<String, Object> robotModelSection(RobotModel model, boolean simulator) {
        if (simulator) {
            Map<String, Object> p = model.parameters();
            p.putAll(LaserConfig.URG_04LX.parameters());
            Map<String, String> sources = RobotModel.sources();
            sources.putAll(LaserConfig.urg04lxSources());
            p.put("sources", sources);
            return p;
        }
        Map<String, Object> external = new LinkedHashMap<>();
        external.put("name", "external");
        external.put("top_speed_mps", model.topSpeedMps());
        return external;
    }

    private static double round3(double v) {
        return Rounding.toDecimals(v, 3);
    }

    private static String trim(double v) {
        return v == Math.rint(v) ? Long.toString((long) v) : Double.toString(v);
    }
}
