package io.rtaware.sim.ros2;

import io.rtaware.core.agent.AgentThread;
import io.rtaware.core.time.EpochClock;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.robot.msg.VelocityCommand;
import io.rtaware.ros2.graph.FirstPublisherFilter;
import io.rtaware.ros2.graph.QosProfile;
import io.rtaware.ros2.graph.Ros2Context;
import io.rtaware.ros2.graph.Ros2Names;
import io.rtaware.ros2.graph.Ros2Node;
import io.rtaware.ros2.graph.Ros2Publisher;
import io.rtaware.ros2msg.LaserScanCodec;
import io.rtaware.ros2msg.OdometryCodec;
import io.rtaware.ros2msg.RobotTopics;
import io.rtaware.ros2msg.Ros2Header;
import io.rtaware.ros2msg.Ros2Types;
import io.rtaware.ros2msg.TransformMessages;
import io.rtaware.ros2msg.TwistCodec;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.cdr.CdrWriter;
import io.rtaware.ros2msg.value.PlanarTransform;
import io.rtaware.sim.server.PlayerSimServer;
import io.rtaware.sim.world.World;
import io.rtaware.zenoh.SampleBuffer;
import io.rtaware.zenoh.ZenohException;
import io.rtaware.zenoh.ZenohMailbox;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.agrona.concurrent.Agent;
import org.agrona.concurrent.AgentTerminationException;
import org.agrona.concurrent.NoOpIdleStrategy;

/**
 * The world of a running {@link PlayerSimServer} as a ROS 2 robot: the node {@value #NODE_NAME}
 * publishes {@code scan} ({@code sensor_msgs/msg/LaserScan}, sensor-data QoS), {@code odom} and
 * {@code ground_truth} (both {@code nav_msgs/msg/Odometry}) whenever the world has new ones, and
 * drives the robot with the {@code geometry_msgs/msg/Twist} messages it receives on
 * {@code cmd_vel}; topic names are relative to the robot's namespace. Frames as REP 105 names
 * them and a robot driver publishes them: scans in {@value RobotTopics#LASER_FRAME}, odometry in
 * {@value RobotTopics#ODOM_FRAME} with child {@value RobotTopics#BASE_FRAME}, ground truth in {@value RobotTopics#WORLD_FRAME} (the
 * world's fixed frame; no transform joins it to {@value RobotTopics#ODOM_FRAME}, which drifts from it); on
 * {@code /tf} the transform {@value RobotTopics#ODOM_FRAME} to {@value RobotTopics#BASE_FRAME} of every odometry
 * sample, stamped as the sample; on {@code /tf_static} {@value RobotTopics#BASE_FRAME} to
 * {@value RobotTopics#LASER_FRAME} (the laser at the robot's centre), offered transient local as tf2's
 * static broadcaster offers it and, since this Zenoh layer keeps no history for late
 * subscribers, published again every {@value #STATIC_REPEAT_MS} ms of wall time. Header stamps
 * are world time (the simulator's clock, as ROS's {@code use_sim_time}) when the data was
 * measured: a scan's is its first beam's ({@link World#scanFirstBeamNs()}, as ROS 2's
 * {@code LaserScan} defines it), an odometry sample's its sample time; {@value #CLOCK}
 * ({@code rosgraph_msgs/msg/Clock}, best effort, keep last 1, as ROS 2's clock publishers) carries
 * that world time whenever it moves on, so a stock node with {@code use_sim_time} reads the stamps
 * in the time they were made in. Attachments carry the
 * wall-clock source timestamp. One thread of its own ({@value #THREAD_NAME}, an {@link AgentThread})
 * does all of it, waiting up to {@value #POLL_MS} ms for a command between looks at the world; the
 * Player server keeps serving. A failure ends the thread, and {@link #failure()} says why.
 *
 * <p>Only the first publisher heard on {@code cmd_vel} drives the robot (told apart by the gid of
 * the rmw_zenoh attachment, {@link FirstPublisherFilter}; another one once the first has been
 * silent for {@value #COMMANDER_SILENCE_NS} ns of wall time): a foreign velocity publisher is
 * reported once ({@link #notices()} and the report callback) and its Twists are dropped.
 *
 * <p>Thread-safe: {@link #close()} from any thread.
 */
public final class Ros2SimRobot implements AutoCloseable {

    /** The simulator's node name in the ROS graph. */
    public static final String NODE_NAME = "rtaware_sim";
    /** Topics, relative to the namespace. */
    public static final String SCAN = "scan";
    /** Odometry topic. */
    public static final String ODOM = "odom";
    /** Ground-truth topic. */
    public static final String GROUND_TRUTH = "ground_truth";
    /** Velocity command topic. */
    public static final String CMD_VEL = "cmd_vel";
    /**
     * The simulated time topic (absolute, as ROS 2 publishes it): the world's time, which stamps
     * every message of the robot, so that a node with {@code use_sim_time} follows it.
     */
    public static final String CLOCK = "/clock";
    /** Wall time between two publications of {@code /tf_static}. */
    public static final long STATIC_REPEAT_MS = 1000;
    /** The name of the robot's thread. */
    public static final String THREAD_NAME = "rtaware-sim-ros2";

    /** Wall time the followed {@code cmd_vel} publisher may be silent before another drives: 1 s. */
    public static final long COMMANDER_SILENCE_NS = 1_000_000_000L;

    private static final int POLL_MS = 2;
    private static final long POLL_NS = TimeUnit.MILLISECONDS.toNanos(POLL_MS);
    private static final int MAX_MESSAGE_BYTES = 64 * 1024;
    /** {@code /tf_static}: the laser at the robot's centre, as the simulator measures its scans. */
    private static final List<PlanarTransform> STATIC_TRANSFORMS = List.of(RobotTopics.LASER_MOUNT);
    /** The history depth tf2's broadcaster offers on {@code /tf}. */
    private static final int TF_DEPTH = 100;

    private final PlayerSimServer server;
    private final Ros2Context context;
    private final Ros2Node node;
    private final Ros2Publisher scanPub;
    private final Ros2Publisher odomPub;
    private final Ros2Publisher truthPub;
    private final Ros2Publisher tfPub;
    private final Ros2Publisher tfStaticPub;
    private final Ros2Publisher clockPub;
    private final ZenohMailbox mailbox;
    /** The robot's loop, started once the node is declared. */
    private volatile AgentThread loop;
    private final EpochClock epoch = new EpochClock();

    private final LaserScanCodec scanCodec = new LaserScanCodec();
    private final OdometryCodec odomCodec = new OdometryCodec(RobotTopics.BASE_FRAME);
    private final TwistCodec twistCodec = new TwistCodec();
    private final CdrWriter writer = new CdrWriter(MAX_MESSAGE_BYTES);
    private final CdrReader reader = new CdrReader();
    private final Ros2Header header = new Ros2Header();
    private final SampleBuffer sample = new SampleBuffer(1024, 64);
    private final byte[] bytes = new byte[1024];
    private final VelocityCommand command = new VelocityCommand();
    private final LaserScan scan = new LaserScan();
    private final Odometry odom = new Odometry();
    private final Odometry truth = new Odometry();
    private final boolean[] news = new boolean[2];
    private final List<String> notices = new CopyOnWriteArrayList<>();
    private final FirstPublisherFilter commanders;

    private volatile boolean closing;
    private volatile long commands;
    private volatile long badCommands;
    private volatile String failure;
    private double lastScanTimeS = Double.NaN;
    private double lastOdomTimeS = Double.NaN;
    private long scanFirstBeamNs;
    private long worldTimeNs;
    private long clockSentNs = -1;
    private long nextStaticNs = System.nanoTime();

    private Ros2SimRobot(PlayerSimServer server, Ros2Context context, String namespace, Consumer<String> report)
            throws ZenohException {
        this.server = server;
        this.commanders = new FirstPublisherFilter(Ros2Names.resolveTopic(Ros2Names.namespace(namespace), CMD_VEL),
                COMMANDER_SILENCE_NS, line -> {
                    notices.add(line);
                    report.accept(line);
                });
        this.context = context;
        this.node = context.createNode(namespace, NODE_NAME);
        this.scanPub = node.createPublisher(SCAN, scanCodec.type(), QosProfile.sensorData(), MAX_MESSAGE_BYTES);
        this.odomPub = node.createPublisher(ODOM, odomCodec.type(), QosProfile.defaults(), MAX_MESSAGE_BYTES);
        this.truthPub = node.createPublisher(GROUND_TRUTH, odomCodec.type(), QosProfile.defaults(), MAX_MESSAGE_BYTES);
        this.tfPub = node.createPublisher(RobotTopics.TF, Ros2Types.TF_MESSAGE, new QosProfile(true, false, TF_DEPTH),
                MAX_MESSAGE_BYTES);
        this.tfStaticPub = node.createPublisher(RobotTopics.TF_STATIC, Ros2Types.TF_MESSAGE, new QosProfile(true, true, 1),
                MAX_MESSAGE_BYTES);
        // As ROS 2's clock publishers (rclcpp's ClockQoS): best effort, keep last 1.
        this.clockPub = node.createPublisher(CLOCK, Ros2Types.CLOCK, new QosProfile(false, false, 1), MAX_MESSAGE_BYTES);
        this.mailbox = context.session().newMailbox(16);
        node.subscribe(CMD_VEL, twistCodec.type(), QosProfile.defaults(), mailbox, 0);
    }

    /**
     * Starts publishing the server's world.
     *
     * @param server the running simulator
     * @param context an open context, owned by the robot from now on
     * @param namespace the robot's namespace ({@code /} for none)
     * @param report receives, on the robot's thread, one line per event reported once (a foreign
     *     {@code cmd_vel} publisher)
     * @return the running robot
     * @throws ZenohException if a declaration fails (the context is closed then)
     */
    public static Ros2SimRobot start(PlayerSimServer server, Ros2Context context, String namespace,
                                     Consumer<String> report) throws ZenohException {
        Objects.requireNonNull(server, "server");
        Objects.requireNonNull(report, "report");
        try {
            Ros2SimRobot robot = new Ros2SimRobot(server, context, namespace, report);
            // take() waits for a command, so the loop needs no idle strategy of its own
            robot.loop = AgentThread.start(robot.new Serving(), NoOpIdleStrategy.INSTANCE, robot::stopped);
            return robot;
        } catch (ZenohException | RuntimeException e) {
            context.close();
            throw e;
        }
    }

    /**
     * The robot's loop: obeys the commands that came (waiting up to {@value #POLL_MS} ms for the
     * first), then publishes what the world has new; a closed mailbox or a failure ends it.
     */
    private final class Serving implements Agent {
        @Override
        public int doWork() {
            int work;
            try {
                work = serveOnce();
            } catch (ZenohException | RuntimeException e) {
                throw new AgentTerminationException(e);
            }
            if (work < 0) {
                throw new AgentTerminationException("the mailbox closed"); // the session is closing: not a failure
            }
            return work;
        }

        @Override
        public String roleName() {
            return THREAD_NAME;
        }
    }

    /** @return commands obeyed, or -1 when the mailbox has closed */
    private int serveOnce() throws ZenohException {
        ZenohMailbox.Take took = mailbox.take(POLL_NS, sample);
        int work = 0;
        while (took == ZenohMailbox.Take.SAMPLE || took == ZenohMailbox.Take.TOO_LARGE) {
            obey(took);
            work++;
            took = mailbox.take(0, sample);
        }
        if (took == ZenohMailbox.Take.CLOSED) {
            return -1;
        }
        publishNews();
        return work;
    }

    /** The loop ended: a failure is kept for {@link #failure()} unless the robot was being closed. */
    private void stopped(Throwable error) {
        Throwable cause = error instanceof AgentTerminationException ? error.getCause() : error;
        if (cause != null && !closing) {
            failure = cause.getMessage() == null ? cause.toString() : cause.getMessage();
        }
    }

    private void obey(ZenohMailbox.Take took) {
        if (took == ZenohMailbox.Take.TOO_LARGE) {
            badCommands++;
            return;
        }
        if (!commanders.accept(sample.attachment(), sample.attachmentLength(), System.nanoTime())) {
            return; // a foreign velocity publisher: counted by the filter, reported once
        }
        int length = sample.payloadLength();
        sample.payload().get(0, bytes, 0, length);
        try {
            twistCodec.decode(reader.wrap(bytes, 0, length), header, command);
        } catch (RuntimeException e) {
            badCommands++;
            return;
        }
        if (!Double.isFinite(command.vxMps) || !Double.isFinite(command.omegaRadPerSec)) {
            badCommands++;
            return;
        }
        commands++;
        server.withWorld(w -> {
            w.command(command.vxMps, command.omegaRadPerSec);
            return null;
        });
    }

    private void publishNews() throws ZenohException {
        boolean[] fresh = server.withWorld(this::copyNews);
        long nowEpochNs = epoch.epochNanos();
        if (fresh[0]) {
            scanCodec.encode(header.set(scanFirstBeamNs, RobotTopics.LASER_FRAME), scan, writer);
            scanPub.publish(writer.buffer(), writer.size(), nowEpochNs);
        }
        if (fresh[1]) {
            long stampNs = Math.round(odom.serverTimeS * 1e9);
            odomCodec.encode(header.set(stampNs, RobotTopics.ODOM_FRAME), odom, writer);
            odomPub.publish(writer.buffer(), writer.size(), nowEpochNs);
            TransformMessages.begin(writer, 1);
            TransformMessages.transform(writer, stampNs, RobotTopics.ODOM_FRAME, RobotTopics.BASE_FRAME, odom.xM, odom.yM, odom.yawRad);
            tfPub.publish(writer.buffer(), writer.size(), nowEpochNs);
            odomCodec.encode(header.set(stampNs, RobotTopics.WORLD_FRAME), truth, writer);
            truthPub.publish(writer.buffer(), writer.size(), nowEpochNs);
        }
        if (worldTimeNs > clockSentNs) {
            writer.begin();
            writer.writeInt32((int) (worldTimeNs / 1_000_000_000L));
            writer.writeInt32((int) (worldTimeNs % 1_000_000_000L));
            clockPub.publish(writer.buffer(), writer.size(), nowEpochNs);
            clockSentNs = worldTimeNs;
        }
        if (System.nanoTime() - nextStaticNs >= 0) {
            TransformMessages.write(writer, worldTimeNs, STATIC_TRANSFORMS);
            tfStaticPub.publish(writer.buffer(), writer.size(), nowEpochNs);
            nextStaticNs += TimeUnit.MILLISECONDS.toNanos(STATIC_REPEAT_MS);
        }
    }

    private boolean[] copyNews(World w) {
        worldTimeNs = w.timeNs();
        news[0] = w.scan().serverTimeS != lastScanTimeS;
        news[1] = w.odometry().serverTimeS != lastOdomTimeS;
        if (news[0]) {
            scan.copyFrom(w.scan());
            lastScanTimeS = scan.serverTimeS;
            scanFirstBeamNs = w.scanFirstBeamNs();
        }
        if (news[1]) {
            odom.copyFrom(w.odometry());
            lastOdomTimeS = odom.serverTimeS;
            truth.xM = w.xM();
            truth.yM = w.yM();
            truth.yawRad = w.yawRad();
            truth.vxMps = w.speedMps();
            truth.vyMps = 0.0;
            truth.omegaRadPerSec = w.turnRateRadPerS();
            truth.serverTimeS = odom.serverTimeS;
        }
        return news;
    }

    /** @return the node's liveliness key and those of its publishers */
    public List<String> tokenKeys() {
        return List.of(node.nodeToken(), scanPub.tokenKey(), odomPub.tokenKey(), truthPub.tokenKey(), tfPub.tokenKey(),
                tfStaticPub.tokenKey());
    }

    /** @return Twist messages obeyed so far */
    public long commands() {
        return commands;
    }

    /** @return Twist messages dropped because another publisher than the one followed sent them */
    public long foreignCommands() {
        return commanders.ignored();
    }

    /** @return one line per event reported once (a foreign {@code cmd_vel} publisher), a snapshot */
    public List<String> notices() {
        return List.copyOf(notices);
    }

    /** @return Twist messages dropped because they could not be decoded or were not finite */
    public long badCommands() {
        return badCommands;
    }

    /** @return scans published so far */
    public long scansPublished() {
        return scanPub.published();
    }

    /** @return why the publishing thread stopped early, or null */
    public String failure() {
        return failure;
    }

    /** Stops the thread, then closes the session (and with it the node's tokens). */
    @Override
    public void close() throws ZenohException {
        closing = true;
        loop.close();
        context.close();
    }
}
