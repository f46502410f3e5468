package io.rtaware.app.run;

import io.rtaware.app.UserError;
import io.rtaware.app.cli.CommandMonitor;
import io.rtaware.app.live.LiveView;
import io.rtaware.app.live.RunScene;
import io.rtaware.app.ros2.ExportOptions;
import io.rtaware.app.ros2.Ros2Link;
import io.rtaware.app.ros2.Ros2Options;
import io.rtaware.core.monitor.ConsoleReporter;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.monitor.TaskCounters;
import io.rtaware.core.monitor.TaskInfo;
import io.rtaware.core.task.ErrorPolicy;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.Clock;
import io.rtaware.core.trace.TraceRecorder;
import io.rtaware.app.rt.RealtimeThreads;
import io.rtaware.nav.NavConfig;
import io.rtaware.nav.NavController;
import io.rtaware.player.client.PlayerClient;
import io.rtaware.ros2.export.MonitorExporter;
import io.rtaware.player.client.PlayerClientOptions;
import io.rtaware.player.client.PlayerCounters;
import io.rtaware.player.protocol.DeviceAddress;
import io.rtaware.player.protocol.SimulationPose2d;
import io.rtaware.player.task.PlayerConfig;
import io.rtaware.player.task.PlayerDataTask;
import io.rtaware.robot.geometry.Point2d;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.robot.msg.CourseStatus;
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
import io.rtaware.sim.world.World;
import java.io.IOException;
import java.io.PrintStream;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.LockSupport;

/**
 * One robot run of the paper's course: the composition root of {@code rtaware run}. Starts the
 * built-in simulator on a free loopback port (or uses an external Player server), wires the
 * Player data task and the navigation behaviors onto one monitor, watches the run from outside
 * (ground truth, progress, time limit), and on every way out (finish, time limit, stuck, Ctrl-C,
 * a crash, a lost connection) stops the robot first and then writes the report.
 */
public final class RobotRun {

    /** Task name of the Player data task in reports. */
    public static final String PLAYER_TASK = "player";
    private static final long SAMPLE_PERIOD_NS = 100_000_000L;
    private static final double STUCK_MIN_MOVE_M = 0.05;
    private static final double LOST_SERVER_AFTER_S = 5.0;
    /** Also required, so a loaded machine that stalls the scaled world briefly is not a lost server. */
    private static final double LOST_SERVER_AFTER_WALL_S = 3.0;

    private final RunOptions options;
    /** {@code --ros2}: a ROS 2 robot over Zenoh instead of a Player server. */
    private final Optional<Ros2Options> ros2;
    /** {@code --export}: keys and health published over ROS 2. */
    private final Optional<ExportOptions> export;
    /** Rising edges of the stall flag: the contact count when the server is not the built-in simulator. */
    private final AtomicLong stallEdges = new AtomicLong();
    private final PrintStream out;
    private final PrintStream err;

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
     * Runs to the end.
     *
     * @return the exit status: 0 for a finished run (completed, timeout, stuck), 1 for an error,
     *     130 if interrupted
     * @throws UserError for a bad scenario or an unreachable server
     * @throws IOException if the simulator cannot start or the report cannot be written
     */
    public int execute() throws IOException {
        Scenario scenario = loadScenario();
        Clock clock = Clock.forTimeScale(options.timeScale());

        PlayerSimServer server = null;
        String host = options.playerHost();
        int port = options.playerPort();
        if (ros2.isPresent() && !options.builtInSimulator()) {
            throw new UserError("--ros2 and --player exclude each other (a ROS 2 robot is reached with --zenoh)");
        }
        boolean externalRos2 = ros2.isPresent() && ros2.get().router() != null;
        if (options.builtInSimulator() && !externalRos2) {
            if (scenario.map().isEmpty()) {
                throw new UserError("scenario '" + scenario.name() + "' has no map; the built-in simulator needs one (or use --player HOST:PORT)");
            }
            server = SimCommandSupport.start(scenario, clock, ServerConfig.defaults(0), options.seed());
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
            return runAgainst(scenario, clock, host, port, server, link);
        } finally {
            if (link != null) {
                link.close();
            }
            if (server != null) {
                server.close();
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

    private Scenario loadScenario() {
        try {
            return ScenarioLoader.load(options.scenario());
        } catch (ScenarioException e) {
            throw new UserError(e.getMessage());
        }
    }

    private int runAgainst(Scenario scenario, Clock clock, String host, int port, PlayerSimServer server,
                           Ros2Link link) throws IOException {
        NavConfig navConfig = navConfig(scenario);
        NavController nav = new NavController(navConfig);
        TaskSpec dataTask = link != null ? link.taskSpec() : new TaskSpec(PLAYER_TASK, Schedule.continuous(),
                ErrorPolicy.CONTINUE, new PlayerDataTask(PlayerConfig.of(host, port).withReconnect(true, 500, 8000)));

        Monitor.Builder builder = Monitor.builder(clock).task(dataTask);
        nav.taskSpecs().forEach(builder::task);
        if (options.realtime()) {
            builder.threadSetup(RealtimeThreads.configure(RealtimeThreads.DEFAULT_TOP_PRIORITY, Map.of(), err));
        }
        Monitor monitor = CommandMonitor.build(builder);
        MonitorExporter exporter = export.map(e -> e.start(monitor, RunExports.keys(nav), err)).orElse(null);
        ConsoleReporter console = CommandMonitor.console(monitor, options.quiet(), err);
        TraceRecorder trace = options.trace().attach(monitor);

        AtomicReference<String> outcome = new AtomicReference<>();
        AtomicReference<String> reason = new AtomicReference<>();
        List<Referee> refereeHolder = new ArrayList<>(1);
        CourseStatus course = new CourseStatus();
        long[] startNs = new long[1];
        RunArtifacts artifacts = new RunArtifacts(options, scenario, navConfig, out);
        LiveView live = LiveView.start(options.live(), monitor, new RunScene(scenario.name(), scenario.map().orElse(null),
                scenario.waypoints(), nav.keys(), nav::mediatorCounts, outcome::get), out);
        monitor.onTermination(report -> {
            if (console != null) {
                console.close();
            }
            outcome.compareAndSet(null, "interrupted");
            reason.compareAndSet(null, "interrupted (Ctrl-C or SIGTERM)");
            Referee referee = refereeHolder.isEmpty() ? null : refereeHolder.get(0);
            if (referee != null) {
                referee.close();
            }
            monitor.read(nav.keys().course(), course);
            long collisions = server != null ? server.withWorld(World::contactCount) : stallEdges.get();
            RunSection run = runSection(scenario, nav, course, referee, outcome.get(), reason.get(),
                    clock.nanos() - startNs[0], collisions, server != null);
            live.finish(report, run);
            artifacts.write(report, run, referee, nav.finalMap().orElse(null),
                    scenario.map().orElse(null));
            options.trace().write(trace, out, err);
        });
        Thread hook = monitor.installShutdownHook();

        // Connected before the start, so the first ground-truth sample is the pose at the start.
        Referee.PoseSource truth = poseSource(host, port, monitor);
        monitor.start();
        startNs[0] = clock.nanos();
        Referee referee = new Referee(clock, startNs[0], SAMPLE_PERIOD_NS, truth, () -> totalMisses(monitor));
        refereeHolder.add(referee);
        live.truePose(referee::latest, referee.kind());
        if (!options.quiet()) {
            String robot = link != null ? link.describe() : host + ":" + port + " ("
                    + (server != null ? "built-in simulator" : "external Player server") + ")";
            err.printf(Locale.ROOT, "rtaware run: scenario %s, periods %s, time scale x%s, robot %s, ground truth from %s%n",
                    scenario.name(), options.periods(), trim(options.timeScale()), robot, referee.kind());
        }

        supervise(scenario, clock, startNs[0], monitor, nav, referee, course, outcome, reason);
        CommandMonitor.stop(monitor, hook);
        live.close();
        ExportOptions.stop(exporter, err);
        if (link != null && !options.quiet()) {
            err.println(link.summary());
        }
        return switch (outcome.get()) {
            case "error" -> 1;
            case "interrupted" -> 130;
            default -> 0;
        };
    }

    private static long totalMisses(Monitor monitor) {
        long sum = 0;
        for (int i = 0; i < monitor.tasks().size(); i++) {
            sum += monitor.counters(i).misses();
        }
        return sum;
    }

    /** Watches the run until it ends; records the outcome. Returns when the run is over. */
    private void supervise(Scenario scenario, Clock clock, long startNs, Monitor monitor, NavController nav,
                           Referee referee, CourseStatus course, AtomicReference<String> outcome,
                           AtomicReference<String> reason) {
        long pollWallNs = Math.max(1_000_000L, Math.min(50_000_000L, (long) (50_000_000L / options.timeScale())));
        long lastStatusWallNs = System.nanoTime();
        Odometry odometry = new Odometry();
        VelocityCommand motor = new VelocityCommand();
        boolean wasStalled = false;
        boolean tty = System.console() != null;
        long lastOdometryGeneration = 0;
        long lastOdometryNs = startNs;
        long lastOdometryWallNs = System.nanoTime();
        while (true) {
            LockSupport.parkNanos(pollWallNs);
            if (monitor.isStopping()) {
                return; // Ctrl-C, SIGTERM or a STOP_ALL error: the termination handler records the outcome.
            }
            double elapsedS = (clock.nanos() - startNs) / 1e9;
            monitor.read(nav.keys().course(), course);
            long odometryGeneration = monitor.read(RobotKeys.ODOMETRY, odometry);
            monitor.read(RobotKeys.MOTOR, motor);
            if (odometry.stall && !wasStalled) {
                stallEdges.incrementAndGet();
            }
            wasStalled = odometry.stall;
            if (odometryGeneration != lastOdometryGeneration) {
                lastOdometryGeneration = odometryGeneration;
                lastOdometryNs = clock.nanos();
                lastOdometryWallNs = System.nanoTime();
            }
            String end = null;
            String why = null;
            if (course.done) {
                end = "completed";
                why = "finish reached";
            } else if (elapsedS >= scenario.timeLimitS()) {
                end = "timeout";
                why = String.format(Locale.ROOT, "time limit of %.0f s passed", scenario.timeLimitS());
            } else if (!motor.isStop() && referee.displacementOverLastM(options.stuckAfterS()) < STUCK_MIN_MOVE_M) {
                end = "stuck";
                why = String.format(Locale.ROOT, "moved less than %.2f m in %.0f s while commanded to move",
                        STUCK_MIN_MOVE_M, options.stuckAfterS());
            } else if ((clock.nanos() - lastOdometryNs) / 1e9 > LOST_SERVER_AFTER_S
                    && (System.nanoTime() - lastOdometryWallNs) / 1e9 > LOST_SERVER_AFTER_WALL_S) {
                end = "error";
                why = String.format(Locale.ROOT, "no odometry from the robot server for %.0f s of world time "
                        + "(%.0f s of wall time): connection lost", LOST_SERVER_AFTER_S, LOST_SERVER_AFTER_WALL_S);
            }
            if (end != null) {
                outcome.compareAndSet(null, end);
                reason.compareAndSet(null, why);
                if (!options.quiet()) {
                    printStatus(monitor, nav, course, elapsedS, referee, tty);
                    err.println();
                    err.println("rtaware run: " + end + ": " + why + "; stopping the robot");
                }
                return;
            }
            if (!options.quiet() && System.nanoTime() - lastStatusWallNs >= (tty ? 250_000_000L : 5_000_000_000L)) {
                lastStatusWallNs = System.nanoTime();
                printStatus(monitor, nav, course, elapsedS, referee, tty);
            }
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
        String line = String.format(Locale.ROOT, "t=%6.1fs  waypoint %d of %d  %5.2f m to go  %5.1f m driven  misses: %s",
                elapsedS, Math.min(course.waypointsReached + 1, course.waypointsTotal), course.waypointsTotal,
                course.distanceToFinishM, referee.travelledM(), misses);
        if (tty) {
            err.print("\r" + line + "   ");
        } else {
            err.println(line);
        }
        err.flush();
    }

    private NavConfig navConfig(Scenario scenario) {
        NavConfig.Builder b = NavConfig.builder()
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
    private Referee.PoseSource poseSource(String host, int port, Monitor monitor) {
        if (host == null) {
            return odometrySource(monitor);
        }
        try {
            PlayerClient client = PlayerClient.connect(host, port, PlayerClientOptions.defaults(), new PlayerCounters());
            try {
                client.subscribe(DeviceAddress.parse("simulation:0"));
                client.simulationPose2d(0, options.modelName());
                return new Referee.PoseSource() {
                    @Override
                    public Pose2d pose() throws IOException {
                        SimulationPose2d p = client.simulationPose2d(0, options.modelName());
                        return new Pose2d(p.xM(), p.yM(), p.yawRad());
                    }

                    @Override
                    public String kind() {
                        return "ground_truth";
                    }

                    @Override
                    public void close() throws IOException {
                        client.close();
                    }
                };
            } catch (IOException e) {
                client.close();
            }
        } catch (IOException e) {
            // No second connection: fall back to odometry below.
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

    private RunSection runSection(Scenario scenario, NavController nav, CourseStatus course,
                                  Referee referee, String outcome, String why, long elapsedNs, long collisions,
                                  boolean simulator) {
        Pose2d last = referee == null ? null : referee.latest();
        Point2d finish = scenario.finish();
        double toFinish = last == null ? Double.NaN : last.position().distanceTo(finish);
        var counts = nav.mediatorCounts();
        Map<String, Long> mediator = new LinkedHashMap<>();
        mediator.put("obstacle", counts.obstacle());
        mediator.put("waypoint", counts.waypoint());
        mediator.put("stop", counts.stop());
        return new RunSection(scenario.name(), options.periods().millis(), outcome, "completed".equals(outcome),
                round3(elapsedNs / 1e9), course.waypointsReached, course.waypointsTotal, round3(toFinish),
                round3(referee == null ? 0 : referee.travelledM()), collisions, mediator,
                referee == null ? "odometry" : referee.kind(), simulator ? "simulator" : "stall",
                options.timeScale(), options.seed(), options.gridResolutionM(), counts.staleStops(), why);
    }

    private static double round3(double v) {
        return Double.isNaN(v) ? v : Math.round(v * 1000.0) / 1000.0;
    }

    private static String trim(double v) {
        return v == Math.rint(v) ? Long.toString((long) v) : Double.toString(v);
    }
}
