package io.rtaware.robotrun;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.time.ScaledClock;
import io.rtaware.nav.ControllerMetadata;
import io.rtaware.record.RecordingPlan;
import io.rtaware.record.RecordingTap;
import io.rtaware.record.RunRecorder;
import io.rtaware.record.TapChannel;
import io.rtaware.replay.ReplayProviders;
import io.rtaware.robot.geometry.Point2d;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.sim.scenario.Scenario;
import io.rtaware.sim.scenario.ScenarioLoader;
import io.rtaware.sim.server.PlayerSimServer;
import io.rtaware.sim.server.ServerConfig;
import io.rtaware.sim.server.SimCommandSupport;
import io.rtaware.sim.world.RobotModel;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;

/**
 * The nav controller runs on the built-in simulator from code, without the command line, as
 * {@link NavRun}'s documentation shows: a course whose far waypoint cannot be reached within a
 * time limit of one world second ends by the time limit, whatever the machine's speed, the
 * recorder it was given has the ending on {@code /rosout}, and the termination handler's
 * {@link NavRun#finish()} gives the report's {@code run} section.
 */
class NavRunTest {

    private static Scenario oneSecondCourse() {
        Scenario room = ScenarioLoader.load(ScenarioLoader.PAPER_ROOM);
        // 3 m away at 0.1 m/s: out of reach in one second of world time.
        return new Scenario("one-second", room.map(), room.start(),
                List.of(new Point2d(room.start().xM() + 3, room.start().yM())), 0.3, 1.0);
    }

    @Test
    void aRunFromCodeEndsByItsTimeLimitAndReportsIt() throws Exception {
        Scenario scenario = oneSecondCourse();
        RobotModel model = RobotModel.koala(RobotModel.PAPER_TOP_SPEED_MPS);
        ScaledClock clock = new ScaledClock(10);
        NavRun.Settings settings = new NavRun.Settings(Map.of("obstacle", 40_000_000L), 10, 1, 4, 0.05, 0, 60, "r0");
        AtomicReference<RunSection> finished = new AtomicReference<>();
        RosoutTap tap = new RosoutTap();
        try (RobotLink robot = RobotLink.simulator(SimCommandSupport.start(scenario, model, clock,
                ServerConfig.defaults(0), settings.seed(), settings.robotSeed()))) {
            NavRun run = new NavRun(scenario, model, settings, robot, clock);
            RecordingPlan plan = run.recordingPlan();
            RunRecorder recorder = new RunRecorder((Path) null, List.of(), List.of(), List.of(),
                    new RecordingPlan().withGroundTruth().startingNow(clock.nanos()).tap(tap));
            Monitor monitor = run.monitorBuilder().build();
            run.attach(monitor, recorder);
            monitor.onTermination(report -> finished.set(run.finish()));
            monitor.start();
            run.started();

            RunState.Ending ending = run.superviseUntilEnd(elapsedS -> { });
            monitor.stop();
            recorder.finish(); // the writer thread has sent the tap every line

            // The safety log is the run's, not the command line's: a run from code logs its ending too.
            assertEquals(List.of("20 safety run ended, timeout: time limit of 1 s passed"), tap.lines,
                    "the ending on /rosout, at info level; no collision or near miss on this course");

            assertEquals(RunOutcome.TIMEOUT, ending.outcome());
            assertEquals("time limit of 1 s passed", ending.reason());
            assertEquals(ending, run.state().ending(), "the ending is recorded once");
            assertEquals("built-in simulator", plan.metadata().get("robot"));
            assertTrue(plan.hasGroundTruth(), "the simulator's simulation:0 is a truth source: /ground_truth recorded");
            assertEquals("koala", plan.metadata().get("robot_model"), "the model simulated");
            ReplayProviders.RecordedController controller = ReplayProviders.load(NavRunTest.class.getClassLoader())
                    .controllerOf(plan.metadata());
            assertEquals(NavReplayProvider.ID, controller.provider().id(), "the recording names its replay provider");
            assertEquals(run.navConfig(), ControllerMetadata.navConfig(controller.configuration()),
                    "replay can rebuild the controller");
            assertEquals("/map", plan.topicOf("map"));
        }
        RunSection section = finished.get();
        assertNotNull(section, "the termination handler ran");
        assertEquals("one-second", section.scenario());
        assertEquals("timeout", section.outcome());
        assertTrue(section.runTimeS() >= 1.0, "ran to the limit: " + section.runTimeS());
        assertEquals(List.of("waypoint", "obstacle", "occupancy", "planner"), List.copyOf(section.periodsMs().keySet()));
        assertEquals(40.0, section.periodsMs().get("obstacle"));
        assertEquals("ground_truth", section.measuredOn(), "the simulator's simulation:0 gives the true pose");
        assertEquals("simulator", section.collisionsFrom());
        assertEquals(4L, section.robotSeed());
    }

    /** Keeps the {@code /rosout} lines a recording's tap is sent, as "level name text". */
    private static final class RosoutTap implements RecordingTap {
        final List<String> lines = new CopyOnWriteArrayList<>();
        private volatile int rosout = -1;

        @Override
        public void channel(TapChannel channel) {
            if (channel.topic().equals(RunRecorder.ROSOUT_TOPIC)) {
                rosout = channel.id();
            }
        }

        @Override
        public void message(int channelId, long logTimeNs, byte[] data, int offset, int length) {
            if (channelId != rosout) {
                return;
            }
            CdrReader in = new CdrReader().wrap(data, offset, length);
            in.readInt32(); // stamp: seconds
            in.readInt32(); // and nanoseconds
            int level = in.readInt8();
            StringBuilder name = new StringBuilder();
            StringBuilder text = new StringBuilder();
            in.readString(name);
            in.readString(text);
            lines.add(level + " " + name + " " + text);
        }
    }

    /** A finish 0.2 m ahead of the start, within the 0.3 m tolerance: reached at once. */
    private static Scenario finishAtTheStart() {
        Scenario room = ScenarioLoader.load(ScenarioLoader.PAPER_ROOM);
        return new Scenario("finish-at-start", room.map(), room.start(),
                List.of(new Point2d(room.start().xM() + 0.2, room.start().yM())), 0.3, 30.0);
    }

    /** How a run of {@link #finishAtTheStart()} ended, and its {@code run} section. */
    private record Ended(RunState.Ending ending, RunSection section) {
    }

    /**
     * Runs {@link #finishAtTheStart()} at time scale 10 on the built-in simulator, reached as the
     * built-in simulator or over Player as an external server.
     *
     * @param overPlayer reach the simulator as an external Player server (truth from its simulation:0)
     * @param groundTruthModel the robot's name in simulation:0 (an unknown name: no truth source)
     */
    private static Ended runToTheFinish(boolean overPlayer, String groundTruthModel) throws Exception {
        Scenario scenario = finishAtTheStart();
        RobotModel model = RobotModel.koala(RobotModel.PAPER_TOP_SPEED_MPS);
        ScaledClock clock = new ScaledClock(10);
        NavRun.Settings settings = new NavRun.Settings(Map.of(), 10, 1, 4, 0.05, 0, 60, groundTruthModel);
        AtomicReference<RunSection> finished = new AtomicReference<>();
        try (var server = SimCommandSupport.start(scenario, model, clock, ServerConfig.defaults(0), 1, 4);
             RobotLink robot = overPlayer ? RobotLink.player("127.0.0.1", server.port()) : RobotLink.simulator(server)) {
            NavRun run = new NavRun(scenario, model, settings, robot, clock);
            Monitor monitor = run.monitorBuilder().build();
            run.attach(monitor, null);
            monitor.onTermination(report -> finished.set(run.finish()));
            monitor.start();
            run.started();
            RunState.Ending ending = run.superviseUntilEnd(elapsedS -> { });
            monitor.stop();
            return new Ended(ending, finished.get());
        }
    }

    /** The ending names the true distance of the finish's pass, measured on the same look's true pose. */
    private static void assertTheTruthIsMeasured(Ended run) {
        assertEquals(RunOutcome.COMPLETED, run.ending().outcome());
        RunSection section = run.section();
        RunSection.WaypointPass finish = section.waypointPasses().get(section.waypointPasses().size() - 1);
        assertNotNull(finish.trueDistanceM(), "the true pose is known: " + section);
        assertEquals(String.format(java.util.Locale.ROOT, "finish reached by odometry; %.2f m from it in truth",
                finish.trueDistanceM()), run.ending().reason());
        assertEquals(run.ending().reason(), section.reason(), "the report says the same");
    }

    @Test
    void aFinishReachedByOdometrySaysHowFarTheTruePoseWasFromIt() throws Exception {
        assertTheTruthIsMeasured(runToTheFinish(false, "r0")); // the built-in simulator's own pose
    }

    @Test
    void aPlayerServersSimulationDeviceMeasuresTheTruthOfTheFinish() throws Exception {
        Ended run = runToTheFinish(true, "r0");
        assertEquals("ground_truth", run.section().measuredOn());
        assertTheTruthIsMeasured(run);
    }

    @Test
    void withoutATruthSourceTheFinishIsReachedByOdometryOnly() throws Exception {
        // A Player server whose simulation:0 does not know the model: the referee falls back to odometry.
        Ended run = runToTheFinish(true, "no-such-model");
        assertEquals("odometry", run.section().measuredOn());
        assertEquals(new RunState.Ending(RunOutcome.COMPLETED, "finish reached by odometry"), run.ending(),
                "no truth claimed where none was measured");
        assertNull(run.section().waypointPasses().get(0).trueDistanceM(), "nor a true distance at the pass: "
                + run.section());
    }


    /**
     * A Player server that cannot give this robot's true pose ({@code simulation:0} does not know
     * the model): the recording has no {@code /ground_truth} (the referee watches odometry, which
     * is not truth), names the robot as it is, and calls the model the controller's assumption.
     */
    @Test
    void aRobotWithoutATruthSourceIsRecordedWithoutGroundTruthAndAsWhatItIs() throws Exception {
        Scenario scenario = oneSecondCourse();
        RobotModel model = RobotModel.koala(RobotModel.PAPER_TOP_SPEED_MPS);
        ScaledClock clock = new ScaledClock(10);
        NavRun.Settings settings = new NavRun.Settings(Map.of(), 10, 1, 4, 0.05, 0, 60, "not-in-this-world");
        try (PlayerSimServer server = SimCommandSupport.start(scenario, model, clock, ServerConfig.defaults(0),
                settings.seed(), settings.robotSeed());
             RobotLink robot = RobotLink.player(ServerConfig.LOOPBACK, server.port())) {
            RecordingPlan plan = new NavRun(scenario, model, settings, robot, clock).recordingPlan();

            assertFalse(plan.hasGroundTruth(), "no truth source, no /ground_truth");
            assertEquals("Player at " + ServerConfig.LOOPBACK + ":" + server.port(), plan.metadata().get("robot"));
            assertNull(plan.metadata().get("robot_model"), "the robot's model is not known: " + plan.metadata());
            assertEquals("koala", plan.metadata().get("assumed_robot_model"));
        }
    }

    @Test
    void aRunStoppedBeforeItsStartIsInterrupted() throws Exception {
        Scenario scenario = oneSecondCourse();
        RobotModel model = RobotModel.koala(RobotModel.PAPER_TOP_SPEED_MPS);
        ScaledClock clock = new ScaledClock(1);
        try (RobotLink robot = RobotLink.simulator(SimCommandSupport.start(scenario, model, clock,
                ServerConfig.defaults(0), 1, 4))) {
            NavRun run = new NavRun(scenario, model, NavRun.Settings.defaults(), robot, clock);
            run.attach(run.monitorBuilder().build(), null);

            RunSection section = run.finish();

            assertEquals("interrupted", section.outcome());
            assertNull(run.referee(), "no referee was started");
            assertEquals(0, section.waypointsReached());
        }
    }
}
