package io.rtaware.robotrun;

import io.rtaware.core.agent.AgentThread;
import io.rtaware.core.data.Key;
import io.rtaware.core.time.Clock;
import io.rtaware.nav.NavKeys;
import io.rtaware.record.RecordingPlan;
import io.rtaware.record.RecordingTap;
import io.rtaware.record.RobotRecordingPlan;
import io.rtaware.record.RunRecorder;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.OccupancyGrid;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.robot.msg.RobotKeys;
import io.rtaware.ros2msg.RobotTopics;
import io.rtaware.sim.map.OccupancyMap;
import io.rtaware.sim.scenario.Scenario;
import io.rtaware.sim.server.PlayerSimServer;
import io.rtaware.sim.world.World;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import org.agrona.concurrent.Agent;
import org.agrona.concurrent.SleepingMillisIdleStrategy;

/**
 * The simulated robot as a recording's tap sees a robot (what {@code rtaware sim --foxglove}
 * shows in Foxglove), through the recorder's channels and encoders (a recorder without a file,
 * feeding the tap alone) and the robot's plan ({@link RobotRecordingPlan}):
 * {@code /scan} (frame {@code laser}), {@code /odom}, {@code /ground_truth} (frame {@code world}),
 * {@code /tf} ({@code odom} to {@code base_link}, {@code world} to {@code ground_truth}),
 * {@code /tf_static} ({@code base_link} to {@code laser}) and the scenario's walls on
 * {@code /map} (latched, frame {@code world}). A sampler ({@value #THREAD_NAME}, an {@link AgentThread}) looks at the
 * world every {@value #SAMPLE_PERIOD_MS} ms of wall time and hands each new scan and odometry
 * sample to the recorder (the world is read under its lock, as the Player server does); the
 * recorder's writer thread encodes and sends them. A look that throws is printed once (to
 * standard error) and counted; the sampler goes on.
 */
public final class SimulatorFeed implements AutoCloseable, Agent {

    /** The sampler thread's name. */
    public static final String THREAD_NAME = "rtaware-sim-feed";

    /** Wall time between two looks at the world. */
    public static final long SAMPLE_PERIOD_MS = 5;

    private static final int LASER = 0;
    private static final int ODOMETRY = 1;
    private static final int MAP = 2;

    private final PlayerSimServer server;
    private final Clock clock;
    private final RunRecorder recorder;
    private volatile AgentThread sampler;
    private final LaserScan scan = new LaserScan();
    private final Odometry odometry = new Odometry();
    private final boolean[] news = new boolean[2];
    private double truthXM;
    private double truthYM;
    private double truthYawRad;
    private double lastScanTimeS = Double.NaN;
    private double lastOdometryTimeS = Double.NaN;
    private long scans;
    private long samples;

    private SimulatorFeed(PlayerSimServer server, Clock clock, RunRecorder recorder) {
        this.server = server;
        this.clock = clock;
        this.recorder = recorder;
    }

    /**
     * Starts feeding a tap (the Foxglove server) from the simulator.
     *
     * @param scenario the served scenario (its map becomes {@code /map})
     * @param server the simulator
     * @param clock its world clock
     * @param tap where the recorder's messages go, e.g. a {@code FoxgloveServer}
     * @return the running feed; close it before the simulator
     */
    public static SimulatorFeed start(Scenario scenario, PlayerSimServer server, Clock clock, RecordingTap tap) {
        OccupancyGrid walls = scenario.map().map(OccupancyMap::toGrid).orElse(null);
        int cells = walls == null ? 1 : walls.width() * walls.height();
        Key<OccupancyGrid> mapKey = Key.of(NavKeys.MAP, OccupancyGrid.class, () -> new OccupancyGrid(cells));
        RecordingPlan plan = RobotRecordingPlan.create()
                .withGroundTruth() // the world's own pose of the robot
                .topic(NavKeys.MAP, RobotTopics.MAP, RobotTopics.WORLD_FRAME) // the scenario's walls, where they are
                .latched(NavKeys.MAP)
                .metadata("command", "sim")
                .metadata("scenario", scenario.name())
                .startingNow(clock.nanos())
                .tap(tap);
        RunRecorder recorder;
        try {
            recorder = new RunRecorder((Path) null, List.of(), List.of(),
                    List.of(RobotKeys.LASER, RobotKeys.ODOMETRY, mapKey), plan);
        } catch (IOException e) {
            throw new IllegalStateException("a recorder without a file writes nothing, yet failed", e);
        }
        if (walls != null) {
            recorder.commit(MAP, 1, clock.nanos(), walls);
        }
        SimulatorFeed feed = new SimulatorFeed(server, clock, recorder);
        feed.sampler = AgentThread.start(feed, new SleepingMillisIdleStrategy(SAMPLE_PERIOD_MS), feed::lookFailed);
        return feed;
    }

    /** One look at the world: hands a new scan and a new odometry sample to the recorder. */
    @Override
    public int doWork() {
        boolean[] fresh = server.withWorld(this::copyNews);
        long nowNs = clock.nanos();
        int work = 0;
        if (fresh[0]) {
            recorder.commit(LASER, ++scans, nowNs, scan);
            work++;
        }
        if (fresh[1]) {
            recorder.commit(ODOMETRY, ++samples, nowNs, odometry);
            recorder.groundTruth(nowNs, truthXM, truthYM, truthYawRad);
            work++;
        }
        return work;
    }

    @Override
    public String roleName() {
        return THREAD_NAME;
    }

    private void lookFailed(Throwable error) {
        if (sampler == null || sampler.errors() <= 1) {
            System.err.println(THREAD_NAME + ": a look at the world failed: " + error
                    + " (the sampler goes on; further failures are counted)");
        }
    }

    private boolean[] copyNews(World w) {
        news[0] = w.scan().serverTimeS != lastScanTimeS;
        news[1] = w.odometry().serverTimeS != lastOdometryTimeS;
        if (news[0]) {
            scan.copyFrom(w.scan());
            lastScanTimeS = scan.serverTimeS;
        }
        if (news[1]) {
            odometry.copyFrom(w.odometry());
            lastOdometryTimeS = odometry.serverTimeS;
            truthXM = w.xM();
            truthYM = w.yM();
            truthYawRad = w.yawRad();
        }
        return news;
    }

    /** Stops the sampler and finishes the recorder (its last messages are sent). Idempotent. */
    @Override
    public void close() {
        sampler.close();
        recorder.finish();
    }
}
