package io.rtaware.robotrun;

import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.report.Rounding;
import io.rtaware.core.time.Clock;
import io.rtaware.nav.Behavior;
import io.rtaware.nav.NavConfig;
import io.rtaware.nav.NavController;
import io.rtaware.record.RecordingPlan;
import io.rtaware.record.RunRecorder;
import io.rtaware.robot.geometry.Point2d;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.robot.msg.CourseStatus;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.robot.msg.RobotKeys;
import io.rtaware.robot.msg.VelocityCommand;
import io.rtaware.ros2.export.ExportedKey;
import io.rtaware.sim.map.OccupancyMap;
import io.rtaware.sim.scenario.Scenario;
import io.rtaware.sim.server.PlayerSimServer;
import io.rtaware.sim.world.LaserConfig;
import io.rtaware.sim.world.RobotModel;
import io.rtaware.sim.world.World;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.locks.LockSupport;

/**
 * One run of the paper's navigation controller on a robot, from code: the library entry point
 * that {@code rtaware run} wires. The controller ({@link NavController}, built from the
 * scenario's course, the robot model and the {@link Settings}) and its robot's data task
 * ({@link RobotLink}) go onto one monitor; a {@link Referee} watches the robot from outside; a
 * {@link Supervisor} applies the end-of-run rules (finish, time limit, stuck, lost server, safety
 * fault); the {@code run} section of the report says how it went. In a user's {@code main}:
 *
 * <pre>{@code
 * try (RobotLink robot = RobotLink.simulator(SimCommandSupport.start(scenario, model, clock,
 *         ServerConfig.defaults(0), seed, robotSeed))) {
 *     NavRun run = new NavRun(scenario, model, NavRun.Settings.defaults(), robot, clock);
 *     Monitor monitor = run.monitorBuilder().build();
 *     run.attach(monitor, null);                    // before the start: ground truth connects
 *     monitor.onTermination(report -> System.out.println(run.finish().outcome()));
 *     monitor.start();
 *     run.started();
 *     run.superviseUntilEnd(elapsedS -> { });       // returns at the finish, time limit, ...
 *     monitor.stop();                               // the robot-facing tasks first, then the report
 * }
 * }</pre>
 *
 * <p>Every way out is recorded once ({@link RunState}): the supervisor's ending, else (Ctrl-C, a
 * fatal error) {@link RunOutcome#INTERRUPTED} when {@link #finish()} runs. Not thread-safe except
 * {@link #state()}, which the live view and a termination handler read from other threads.
 */
public final class NavRun {

    /** World time between two ground-truth samples: 100 ms. */
    public static final long SAMPLE_PERIOD_NS = 100_000_000L;

    /** Margin of the controller's grid around the scenario's map, metres. */
    private static final double GRID_MARGIN_M = 1.0;
    /** Half the side of the controller's grid around the start when the scenario has no map, metres. */
    private static final double MAPLESS_HALF_SIDE_M = 10.0;

    /**
     * What the run is asked to do besides the course.
     *
     * @param periodsNs the behaviors' periods by task name (those not named keep the paper's Set 4)
     * @param timeScale world seconds per wall second (reported; the clock is the caller's)
     * @param seed the simulator's noise seed (reported)
     * @param robotSeed the simulated robot's error seed (reported for the simulator)
     * @param gridResolutionM the controller's occupancy grid cell size
     * @param inflationMarginM the clearance the planner adds to the robot's radius
     * @param stuckAfterS world seconds without progress, while commanded to move, after which the robot is stuck
     * @param groundTruthModel the robot's model name in the simulation ({@code simulation:0})
     */
    public record Settings(Map<String, Long> periodsNs, double timeScale, long seed, long robotSeed,
                           double gridResolutionM, double inflationMarginM, double stuckAfterS,
                           String groundTruthModel) {

        /**
         * Copies the periods.
         *
         * @param periodsNs the behaviors' periods by task name
         * @param timeScale world seconds per wall second
         * @param seed the simulator's noise seed
         * @param robotSeed the simulated robot's error seed
         * @param gridResolutionM the occupancy grid cell size
         * @param inflationMarginM the planner's clearance beyond the robot's radius
         * @param stuckAfterS the stuck window in world seconds
         * @param groundTruthModel the robot's model name in the simulation
         */
        public Settings {
            periodsNs = Map.copyOf(periodsNs);
            Objects.requireNonNull(groundTruthModel, "groundTruthModel");
        }

        /** @return {@code rtaware run}'s defaults: Set 4, time scale 1, seeds 1 and 4, 5 cm grid, no margin, 60 s, {@code r0} */
        public static Settings defaults() {
            return new Settings(Map.of(), 1.0, 1, 4, 0.05, 0, 60, "r0");
        }
    }

    /** Hears each look of the supervisor, for a status line. */
    @FunctionalInterface
    public interface Status {
        /** @param elapsedS world seconds since the start */
        void look(double elapsedS);
    }

    private final Scenario scenario;
    private final RobotModel model;
    private final Settings settings;
    private final RobotLink link;
    private final Clock clock;
    private final NavConfig navConfig;
    private final NavController nav;
    private final RunState state;
    private final List<RunSection.WaypointPass> passes = new CopyOnWriteArrayList<>();
    private final CourseStatus course = new CourseStatus();
    private Monitor monitor;
    /** The true pose's source, or null when nothing knows it; valid once {@link #trueSourceOpened}. */
    private Referee.PoseSource trueSource;
    private boolean trueSourceOpened;
    /** The referee's source: {@link #trueSource}, else the robot's odometry. */
    private Referee.PoseSource truthSource;
    private Referee.PoseSource truth;
    private long startNs;
    private Referee referee;
    private Supervisor supervisor;
    /** The safety events on the recording's {@code /rosout}; set by {@link #attach}. */
    private SafetyLog safety;
    private MonitorView view;

    /**
     * @param scenario the course
     * @param model the robot model (its top speed, stopping distance and laser delay shape the controller)
     * @param settings periods, grid, margins and what the report repeats
     * @param link the robot
     * @param clock the world clock (the monitor's)
     * @throws IllegalArgumentException if the controller's configuration is not valid (e.g. a grid too large)
     */
    public NavRun(Scenario scenario, RobotModel model, Settings settings, RobotLink link, Clock clock) {
        this.scenario = scenario;
        this.model = model;
        this.settings = settings;
        this.link = link;
        this.clock = clock;
        this.navConfig = navConfig(scenario, model, settings);
        this.nav = new NavController(navConfig);
        this.state = new RunState(clock.nanos());
    }

    /**
     * The controller's configuration for a course and a robot: the robot's top speed, stopping
     * distance and laser delay, the scenario's fastest actor, goal tolerance and waypoints, and a
     * grid over the scenario's map with a metre of margin (20 m around the start without a map).
     *
     * @param scenario the course
     * @param model the robot model
     * @param settings periods, grid resolution and margin
     * @return the configuration
     * @throws IllegalArgumentException if it is not valid
     */
    public static NavConfig navConfig(Scenario scenario, RobotModel model, Settings settings) {
        NavConfig.Builder b = NavConfig.builder()
                .topSpeedMps(model.topSpeedMps())
                .inflationMarginM(settings.inflationMarginM())
                .reactionLimits(model.stoppingDistanceM(model.topSpeedMps()), model.laserDelayNs(LaserConfig.URG_04LX))
                .laserMinRangeM(LaserConfig.URG_04LX.minRangeM())
                .obstacleSpeedMps(scenario.fastestActorMps())
                .periodsNs(settings.periodsNs())
                .goalToleranceM(scenario.goalToleranceM())
                .waypoints(scenario.waypoints());
        OccupancyMap map = scenario.map().orElse(null);
        if (map != null) {
            b.grid(settings.gridResolutionM(), map.originXM() - GRID_MARGIN_M, map.originYM() - GRID_MARGIN_M,
                    map.widthM() + 2 * GRID_MARGIN_M, map.heightM() + 2 * GRID_MARGIN_M);
        } else {
            Pose2d s = scenario.start();
            b.grid(settings.gridResolutionM(), s.xM() - MAPLESS_HALF_SIDE_M, s.yM() - MAPLESS_HALF_SIDE_M,
                    2 * MAPLESS_HALF_SIDE_M, 2 * MAPLESS_HALF_SIDE_M);
        }
        return b.build();
    }

    /** @return a monitor builder on the run's clock with the robot's data task and the controller's tasks */
    public Monitor.Builder monitorBuilder() {
        Monitor.Builder builder = Monitor.builder(clock).task(link.dataTask());
        nav.taskSpecs().forEach(builder::task);
        return builder;
    }

    /**
     * Connects the referee's pose source to the robot, before the monitor starts (so its first
     * sample is the pose at the start): the true pose's source when the robot has one
     * ({@link RobotLink#groundTruth}), else the robot's odometry. From here on {@link #finish()}
     * may run at any moment (a Ctrl-C during start-up runs the termination handlers).
     *
     * @param monitor the monitor built from {@link #monitorBuilder()}
     * @param recorder the run's recorder, which then records every true pose on {@code /ground_truth}
     *     (none when the referee watches odometry) and, on {@code /rosout}, each collision and near
     *     miss of the built-in simulator and how the run ended; or null
     */
    public void attach(Monitor monitor, RunRecorder recorder) {
        this.monitor = monitor;
        this.safety = new SafetyLog(recorder, link.simulator().orElse(null));
        Referee.PoseSource known = trueSource();
        this.truthSource = known != null ? known : RobotLink.odometry(monitor);
        this.truth = known != null ? NavRecording.recordingGroundTruth(known, recorder, clock) : truthSource;
    }

    /** @return the true pose's source, connected on the first call, or null when the robot has none */
    private Referee.PoseSource trueSource() {
        if (!trueSourceOpened) {
            trueSource = link.groundTruth(settings.groundTruthModel(), clock);
            trueSourceOpened = true;
        }
        return trueSource;
    }

    /**
     * Starts watching, right after {@code monitor.start()}: the referee samples the true pose on a
     * thread of its own, and the supervisor's clock starts.
     */
    public void started() {
        startNs = clock.nanos();
        Odometry believed = new Odometry();
        referee = new Referee(clock, startNs, SAMPLE_PERIOD_NS, truth, () -> totalMisses(monitor),
                () -> monitor.read(RobotKeys.ODOMETRY, believed) == 0 ? null : believed.pose()).start();
        view = new MonitorView(monitor, nav, referee, link, scenario.finish());
        supervisor = new Supervisor(view, clock, System::nanoTime, startNs, scenario.timeLimitS(),
                settings.stuckAfterS());
        state.started(startNs, referee, supervisor);
    }

    /**
     * Watches the run until it ends and records the ending: looks every 50 ms of world time (at
     * most every 50 ms and at least every 1 ms of wall time), recording each waypoint the
     * controller newly counts as passed and logging each new collision and near miss and, at the
     * end, the ending on the recorder's {@code /rosout} (if {@link #attach} was given one). Returns early, with null, once the monitor is stopping
     * (Ctrl-C, SIGTERM, a fatal error: the termination handler's {@link #finish()} records it).
     *
     * @param status told of each look
     * @return how the run ended, or null if the monitor stopped first
     */
    public RunState.Ending superviseUntilEnd(Status status) {
        long pollWallNs = Math.max(1_000_000L, Math.min(50_000_000L, (long) (50_000_000L / settings.timeScale())));
        while (true) {
            LockSupport.parkNanos(pollWallNs);
            if (monitor.isStopping()) {
                return null;
            }
            double elapsedS = (clock.nanos() - startNs) / 1e9;
            RunState.Ending ending = supervisor.check();
            recordPasses(elapsedS);
            safety.poll(clock.nanos());
            if (ending != null) {
                state.end(ending.outcome(), ending.reason(), clock.nanos());
                safety.ended(ending, clock.nanos());
                return ending;
            }
            status.look(elapsedS);
        }
    }

    /**
     * Records each waypoint the controller has newly counted as passed, with the true (where
     * ground truth exists) and the believed distance from it at this look (polled, so up to one
     * poll late): the same true pose the supervisor's ending measured.
     */
    private void recordPasses(double elapsedS) {
        int reached = Math.min(view.course().waypointsReached, scenario.waypoints().size());
        if (reached <= passes.size()) {
            return;
        }
        Pose2d truthNow = view.truePose();
        for (int i = passes.size(); i < reached; i++) {
            Point2d wp = scenario.waypoints().get(i);
            Double trueM = truthNow == null ? null : round3(truthNow.position().distanceTo(wp));
            double believedM = view.odometry().pose().position().distanceTo(wp);
            passes.add(new RunSection.WaypointPass(i, round3(elapsedS), trueM, round3(believedM)));
        }
    }

    /**
     * Ends the run's watching, from the monitor's termination handler: records
     * {@link RunOutcome#INTERRUPTED} unless an ending was recorded, stops the referee (a last
     * sample; it closes the pose source) and builds the report's {@code run} section. Call it
     * once, after {@link #attach}.
     *
     * @return the {@code run} section
     */
    public RunSection finish() {
        state.end(RunOutcome.INTERRUPTED, "interrupted (Ctrl-C or SIGTERM)", clock.nanos());
        Referee r = state.referee();
        if (r != null) {
            r.close(); // closes the pose source too
        } else {
            try {
                truth.close(); // stopped before the start: no referee owns the source yet
            } catch (Exception ignored) {
                // the run is over; a failing close of the observer's connection changes nothing
            }
        }
        monitor.read(nav.keys().course(), course);
        PlayerSimServer simulator = link.simulator().orElse(null);
        long collisions = simulator != null ? simulator.withWorld(World::contactCount) : state.stallEdges();
        Map<String, Object> robotErrors = simulator != null ? simulator.withWorld(w -> w.odometryBias().parameters())
                : null;
        double[] safety = simulator != null
                ? simulator.withWorld(w -> new double[] {w.minClearanceM(), w.nearMisses()}) : null;
        return runSection(r, state.ending(), state.elapsedNs(clock.nanos()), collisions, simulator != null,
                robotErrors, safety);
    }

    private RunSection runSection(Referee referee, RunState.Ending ending, long elapsedNs, long collisions,
                                  boolean simulator, Map<String, Object> robotErrors, double[] safety) {
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
        Map<String, Double> periodsMs = new LinkedHashMap<>();
        for (Behavior b : Behavior.values()) {
            periodsMs.put(b.taskName(), navConfig.periods().ns(b) / 1e6);
        }
        return new RunSection(scenario.name(), periodsMs, ending.outcome().jsonName(),
                ending.outcome() == RunOutcome.COMPLETED, round3(runTimeS), course.waypointsReached,
                course.waypointsTotal, toFinish, round3(referee == null ? 0 : referee.travelledM()), collisions,
                mediator, referee == null ? "odometry" : referee.kind(), simulator ? "simulator" : "stall",
                settings.timeScale(), settings.seed(), settings.gridResolutionM(), counts.staleStops(), ending.reason(),
                gaps, round3(Math.max(0, runTimeS - uncoveredS)), RunSection.COMPLETED_MEANS, List.copyOf(passes),
                robotModelSection(simulator), settings.inflationMarginM(),
                simulator ? settings.robotSeed() : null, robotErrors, safety == null ? null : round3(safety[0]),
                safety == null ? null : (long) safety[1], safety == null ? null : World.NEAR_MISS_MARGIN_M,
                safety == null ? null : World.CLEARANCE_LIMIT_M);
    }

    private Map<String, Object> robotModelSection(boolean simulator) {
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

    /**
     * What the run records where: the robot's topics ({@link io.rtaware.record.RobotRecordingPlan}),
     * the controller's map and plan, the true pose when the robot has a source of it (this
     * connects that source, which {@link #attach} then uses), and as {@code rtaware.run} metadata
     * the scenario, the settings, the robot and the controller's configuration
     * ({@link io.rtaware.nav.ControllerMetadata}, what replay rebuilds the controller from). Add
     * the command's own metadata and a tap to it.
     *
     * @return a new plan
     */
    public RecordingPlan recordingPlan() {
        return NavRecording.plan(scenario, settings, navConfig, model.name(), link.recordedAs(),
                link.simulator().orElse(null), trueSource() != null);
    }

    /**
     * @return the run's keys that have a ROS 2 type, in their frames, for the ROS 2 exporter (whose
     *     {@code /tf_static} is {@link io.rtaware.ros2msg.RobotTopics#STATIC_TRANSFORMS})
     */
    public List<ExportedKey<?>> exportedKeys() {
        return NavExports.keys(nav);
    }

    /** @return the controller */
    public NavController controller() {
        return nav;
    }

    /** @return the controller's configuration */
    public NavConfig navConfig() {
        return navConfig;
    }

    /** @return the robot */
    public RobotLink link() {
        return link;
    }

    /** @return what the supervisor, the live view and the termination handler share; thread-safe */
    public RunState state() {
        return state;
    }

    /** @return the referee once {@link #started()}, else null */
    public Referee referee() {
        return state.referee();
    }

    /** @return the report's {@code player} section (with the ground truth's samples), or null for a ROS 2 robot */
    public PlayerSection playerSection() {
        return link.playerSection(truthSource);
    }

    /**
     * @param into where to read the controller's course status (waypoints reached, distances)
     * @return {@code into}
     */
    public CourseStatus readCourse(CourseStatus into) {
        monitor.read(nav.keys().course(), into);
        return into;
    }

    private static long totalMisses(Monitor monitor) {
        long sum = 0;
        for (int i = 0; i < monitor.tasks().size(); i++) {
            sum += monitor.counters(i).misses();
        }
        return sum;
    }

    private static double round3(double v) {
        return Rounding.toDecimals(v, 3);
    }

    /**
     * The supervisor's view of a running monitor: the keys' newest values, the referee, the data
     * task's fault, and the true pose at each look: the built-in simulator's own pose of the
     * robot, else the referee's newest sample when its source measures the truth
     * ({@code simulation:0} of a Player server) and is not lost; none for a robot without a truth
     * source (an external ROS 2 robot, a Player server without {@code simulation:0}).
     */
    private static final class MonitorView implements Supervisor.View {
        private final Monitor monitor;
        private final NavController nav;
        private final Referee referee;
        private final RobotLink link;
        private final Point2d finish;
        private final CourseStatus course = new CourseStatus();
        private final Odometry odometry = new Odometry();
        private final VelocityCommand motor = new VelocityCommand();
        private long odometryGeneration;
        private Pose2d truePose;

        MonitorView(Monitor monitor, NavController nav, Referee referee, RobotLink link, Point2d finish) {
            this.monitor = monitor;
            this.nav = nav;
            this.referee = referee;
            this.link = link;
            this.finish = finish;
        }

        @Override
        public void refresh() {
            monitor.read(nav.keys().course(), course);
            odometryGeneration = monitor.read(RobotKeys.ODOMETRY, odometry);
            monitor.read(RobotKeys.MOTOR, motor);
            PlayerSimServer simulator = link.simulator().orElse(null);
            truePose = simulator != null ? simulator.withWorld(World::pose) : referee.latestTrue();
        }

        @Override
        public double trueDistanceToFinishM() {
            return truePose == null ? Double.NaN : truePose.position().distanceTo(finish);
        }

        /** @return the true pose read at the last refresh, or null where none is known */
        Pose2d truePose() {
            return truePose;
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
            return link.safetyFault();
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
}
