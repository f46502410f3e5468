package io.rtaware.ros2.task;

import io.rtaware.core.data.Input;
import io.rtaware.core.data.Output;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.time.EpochClock;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.robot.msg.RobotKeys;
import io.rtaware.robot.msg.VelocityCommand;
import io.rtaware.robot.validate.ImpossibleDataException;
import io.rtaware.robot.validate.RejectionWatch;
import io.rtaware.robot.validate.SampleLimits;
import io.rtaware.robot.validate.SampleValidator;
import io.rtaware.ros2.graph.FirstPublisherFilter;
import io.rtaware.ros2.graph.QosProfile;
import io.rtaware.ros2.graph.Ros2Context;
import io.rtaware.ros2.graph.Ros2Node;
import io.rtaware.ros2.graph.Ros2Publisher;
import io.rtaware.ros2.graph.SampleAttachment;
import io.rtaware.ros2msg.LaserScanCodec;
import io.rtaware.ros2msg.OdometryCodec;
import io.rtaware.ros2msg.Ros2Header;
import io.rtaware.ros2msg.TwistCodec;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.cdr.CdrWriter;
import io.rtaware.zenoh.SampleBuffer;
import io.rtaware.zenoh.ZenohException;
import io.rtaware.zenoh.ZenohMailbox;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.ByteOrder;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.HdrHistogram.Histogram;

/**
 * The task that connects a ROS 2 robot (rmw_zenoh conventions) to the data store; run it with
 * {@code Schedule.continuous()}. It owns the {@link Ros2Context} it is given: {@link #initialize}
 * creates the node {@value #NODE_NAME}, subscribes the scan and odometry topics and advertises
 * the Twist topic, and declares that it produces {@link RobotKeys#LASER} and
 * {@link RobotKeys#ODOMETRY} and consumes {@link RobotKeys#MOTOR}, like the Player data task.
 *
 * <p>Each {@link #execute} sends the motor command when it has a new generation with a changed
 * value (or again after the keep-alive), then waits at most {@code pollWaitMs} of wall time for
 * a sample and takes every sample queued. Each sample is copied into a buffer allocated once,
 * decoded into a scratch value, validated ({@link SampleValidator}) and only then copied into
 * the output: a sample with a wrong encapsulation, truncated, bigger than the largest accepted
 * message, or with values that cannot be true is counted and dropped, never committed and
 * never fatal. Nothing is allocated per sample on the Java side.
 *
 * <p>Two rules a ROS 2 graph needs beyond the values: when several publishers send on one input
 * topic, only the first one heard is followed ({@link FirstPublisherFilter}, by the gid of the
 * rmw_zenoh attachment; another one after {@value #PUBLISHER_SILENCE_NS} ns of silence of the
 * followed one), the others' samples dropped and counted; and a source's clock that restarts or
 * jumps is followed as a new epoch ({@link SampleValidator}). Each such event is reported once as
 * one line in {@link #notices()}. An input topic that has given no usable sample is looked up in
 * the ROS graph every {@value #TYPE_CHECK_INTERVAL_NS} ns of world time ({@link Ros2Context#publishedTypes}):
 * published only as other types, it can give none (DDS and rmw_zenoh match by type), which is said
 * at once in one line, a notice and a warning of the library log ({@code rt/scan is published as
 * ..., rtaware expects sensor_msgs/msg/LaserScan ...}).
 *
 * <p>{@link #terminate} publishes a zero Twist first, then closes the session. Called by one
 * thread at a time, as every task; {@link #stats()} and {@link #latencySnapshot()} may be called
 * from any thread.
 */
public final class Ros2DataTask implements Task {

    /** World time of rejection-only samples on one topic after which the robot is halted: 1 s. */
    public static final long IMPOSSIBLE_DATA_FAULT_AFTER_NS = 1_000_000_000L;
    /** World time the followed publisher of a topic may be silent before another is followed: 1 s. */
    public static final long PUBLISHER_SILENCE_NS = 1_000_000_000L;
    /**
     * World time between two questions to the ROS graph about an input topic that has given no
     * usable sample yet (which types it is published as), from this long after the first cycle: 1 s.
     */
    public static final long TYPE_CHECK_INTERVAL_NS = 1_000_000_000L;
    private static final System.Logger LOG = System.getLogger(Ros2DataTask.class.getName());

    /** The name of the controller's node in the ROS graph. */
    public static final String NODE_NAME = "rtaware_controller";
    /** Samples kept while a cycle is busy; beyond it the oldest are dropped. */
    private static final int MAILBOX_CAPACITY = 64;
    private static final int SCAN = 0;
    private static final int ODOM = 1;
    private static final long MAX_LATENCY_NS = TimeUnit.SECONDS.toNanos(60);
    /** How far ahead of this machine's clock a wall-clock header stamp may be (another machine's clock): 1 s. */
    private static final long STAMP_AHEAD_NS = TimeUnit.SECONDS.toNanos(1);
    /** {@link #latencySource()} when scans came with rmw_zenoh's attachment. */
    public static final String LATENCY_FROM_ATTACHMENT = "source timestamp (rmw_zenoh attachment)";
    /** {@link #latencySource()} when scans came without one and their header stamps were wall-clock times. */
    public static final String LATENCY_FROM_HEADER = "header stamp (the driver's acquisition time)";

    private final Ros2Context context;
    private final Ros2Topics topics;
    private final long pollWaitNs;
    private final long keepAliveNs;
    private final EpochClock epoch;

    private final SampleBuffer sample;
    private final byte[] bytes;
    private final CdrReader reader = new CdrReader();
    private final CdrWriter writer = new CdrWriter(256);
    private final Ros2Header header = new Ros2Header();
    private final LaserScanCodec scanCodec = new LaserScanCodec();
    private final OdometryCodec odomCodec = new OdometryCodec("base_link");
    private final TwistCodec twistCodec = new TwistCodec();
    private final LaserScan scanScratch = new LaserScan();
    private final Odometry odomScratch = new Odometry();
    private final VelocityCommand zero = new VelocityCommand();
    private final SampleValidator scanValidator;
    private final SampleValidator odomValidator;
    private final FirstPublisherFilter scanPublishers;
    private final FirstPublisherFilter odomPublishers;
    private final List<String> notices = new CopyOnWriteArrayList<>();
    private final RejectionWatch scanWatch = new RejectionWatch(IMPOSSIBLE_DATA_FAULT_AFTER_NS);
    private final RejectionWatch odomWatch = new RejectionWatch(IMPOSSIBLE_DATA_FAULT_AFTER_NS);
    private final PublishedTypeWatch scanTypes;
    private final PublishedTypeWatch odomTypes;
    /** Per topic (SCAN, ODOM): whether its newest sample was malformed or impossible. */
    private final boolean[] newestUnusable = new boolean[2];
    /** Per topic: what the samples since its last usable one were ({@link #IMPOSSIBLE}, {@link #MALFORMED} bits). */
    private final int[] unusableKinds = new int[2];
    /** Per topic: malformed samples in all. */
    private final long[] malformedByTopic = new long[2];
    /** Per topic: why its newest unusable sample was dropped. */
    private final String[] unusableWhy = new String[2];
    private static final int IMPOSSIBLE = 1;
    private static final int MALFORMED = 2;
    private final Histogram scanLatencyNs = new Histogram(MAX_LATENCY_NS, 3);
    private final ThreadMXBean threads = ManagementFactory.getThreadMXBean();

    private Output<Odometry> odometryOut;
    private Output<LaserScan> laserOut;
    private Input<VelocityCommand> motorIn;
    private ZenohMailbox mailbox;
    private Ros2Publisher cmdVel;

    private long motorGeneration = -1;
    private boolean commandSent;
    private double sentVxMps;
    private double sentOmegaRadPerSec;
    private long sentAtNs;
    private long pendingScanSourceNs = Long.MIN_VALUE;
    private long scanEpochsSeen;
    private long odomEpochsSeen;

    private volatile long scans;
    private volatile long odometry;
    private volatile long malformed;
    private volatile long oversized;
    private volatile long overflowedSeen;
    private volatile String lastProblem;
    private volatile long cpuNs;
    private volatile String fault;
    private volatile String latencySource;

    /**
     * @param context an open context, owned by the task from now on (closed by {@link #terminate})
     * @param topics where the robot's data is
     * @param pollWaitMs the longest wall time one cycle waits for a sample
     * @param keepAliveMs world time after which an unchanged motor command is sent again
     * @param maxMessageBytes the largest message accepted
     */
    public Ros2DataTask(Ros2Context context, Ros2Topics topics, int pollWaitMs, long keepAliveMs, int maxMessageBytes) {
        this.context = Objects.requireNonNull(context, "context");
        this.topics = Objects.requireNonNull(topics, "topics");
        if (pollWaitMs <= 0 || keepAliveMs <= 0 || maxMessageBytes <= 0) {
            throw new IllegalArgumentException("pollWaitMs " + pollWaitMs + ", keepAliveMs " + keepAliveMs
                    + " and maxMessageBytes " + maxMessageBytes + " must be positive");
        }
        this.pollWaitNs = TimeUnit.MILLISECONDS.toNanos(pollWaitMs);
        this.keepAliveNs = TimeUnit.MILLISECONDS.toNanos(keepAliveMs);
        this.sample = new SampleBuffer(maxMessageBytes, SampleAttachment.BYTES);
        this.sample.attachment().order(ByteOrder.LITTLE_ENDIAN);
        this.bytes = new byte[maxMessageBytes];
        this.epoch = new EpochClock();
        this.scanValidator = new SampleValidator(topics.qualifiedScan(), SampleLimits.defaults());
        this.odomValidator = new SampleValidator(topics.qualifiedOdom(), SampleLimits.defaults());
        this.scanPublishers = new FirstPublisherFilter(topics.qualifiedScan(), PUBLISHER_SILENCE_NS, notices::add);
        this.odomPublishers = new FirstPublisherFilter(topics.qualifiedOdom(), PUBLISHER_SILENCE_NS, notices::add);
        this.scanTypes = new PublishedTypeWatch(topics.qualifiedScan(), context.wireName(topics.qualifiedScan()),
                scanCodec.type().name(), TYPE_CHECK_INTERVAL_NS, context::publishedTypes, this::warn);
        this.odomTypes = new PublishedTypeWatch(topics.qualifiedOdom(), context.wireName(topics.qualifiedOdom()),
                odomCodec.type().name(), TYPE_CHECK_INTERVAL_NS, context::publishedTypes, this::warn);
    }

    /**
     * Defaults: 20 ms poll wait, 500 ms keep-alive, messages up to 256 KiB.
     *
     * @param context an open context, owned by the task from now on
     * @param topics where the robot's data is
     * @return the task
     */
    public static Ros2DataTask withDefaults(Ros2Context context, Ros2Topics topics) {
        return new Ros2DataTask(context, topics, 20, 500, 256 * 1024);
    }

    /**
     * Declares the keys, creates the node, subscribes and advertises.
     *
     * @param setup the declarations interface
     * @throws ZenohException if a declaration fails
     */
    @Override
    public void initialize(TaskSetup setup) throws ZenohException {
        odometryOut = setup.produce(RobotKeys.ODOMETRY);
        laserOut = setup.produce(RobotKeys.LASER);
        motorIn = setup.consume(RobotKeys.MOTOR);
        Ros2Node node = context.createNode(topics.namespace(), NODE_NAME);
        mailbox = context.session().newMailbox(MAILBOX_CAPACITY);
        node.subscribe(topics.scan(), scanCodec.type(), QosProfile.sensorData(), mailbox, SCAN);
        node.subscribe(topics.odom(), odomCodec.type(), QosProfile.defaults(), mailbox, ODOM);
        cmdVel = node.createPublisher(topics.cmdVel(), twistCodec.type(), QosProfile.defaults(), writer.capacity());
        sentAtNs = Long.MIN_VALUE;
    }

    /**
     * One cycle: send the motor command if needed, wait for samples, take all queued, publish
     * the newest valid ones.
     *
     * @param nowNs world time at the start of the cycle
     * @throws ZenohException if publishing fails or the session was closed
     */
    @Override
    public void execute(long nowNs) throws ZenohException, ImpossibleDataException {
        long cpuStartNs = threads.getCurrentThreadCpuTime();
        try {
            sendMotor(nowNs);
            ZenohMailbox.Take took = mailbox.take(pollWaitNs, sample);
            for (int i = 0; i < MAILBOX_CAPACITY && took != ZenohMailbox.Take.TIMEOUT; i++) {
                if (took == ZenohMailbox.Take.CLOSED) {
                    throw new ZenohException("the ROS 2 subscriptions were closed");
                }
                handle(took, nowNs);
                took = mailbox.take(0, sample);
            }
            long overflowed = mailbox.overflowed();
            if (overflowed != overflowedSeen) {
                overflowedSeen = overflowed;
                lastProblem = "fell behind: " + overflowed + " samples dropped so far";
            }
            if (pendingScanSourceNs != Long.MIN_VALUE) {
                long latencyNs = epoch.epochNanos() - pendingScanSourceNs;
                if (latencyNs >= 0) {
                    scanLatencyNs.recordValue(Math.min(latencyNs, MAX_LATENCY_NS));
                }
                pendingScanSourceNs = Long.MIN_VALUE;
            }
            scanTypes.check(nowNs);
            odomTypes.check(nowNs);
            watchRejections(nowNs);
        } finally {
            cpuNs += threads.getCurrentThreadCpuTime() - cpuStartNs;
        }
    }

    private void handle(ZenohMailbox.Take took, long nowNs) {
        if (took == ZenohMailbox.Take.TOO_LARGE) {
            oversized++;
            lastProblem = "sample of " + sample.payloadLength() + " bytes exceeds the largest accepted ("
                    + bytes.length + ")";
            return;
        }
        boolean scan = sample.channel() == SCAN;
        if (!(scan ? scanPublishers : odomPublishers).accept(sample.attachment(), sample.attachmentLength(), nowNs)) {
            return; // another publisher than the one followed: counted by the filter, reported once
        }
        int length = sample.payloadLength();
        sample.payload().get(0, bytes, 0, length);
        try {
            reader.wrap(bytes, 0, length);
            if (scan) {
                scanCodec.decode(reader, header, scanScratch);
            } else {
                odomCodec.decode(reader, header, odomScratch);
            }
        } catch (RuntimeException e) {
            // Untrusted bytes: whatever the decoder found wrong, the sample is dropped, not the task.
            malformed++;
            lastProblem = (scan ? "scan: " : "odom: ") + e.getMessage();
            int topic = scan ? SCAN : ODOM;
            (scan ? scanTypes : odomTypes).undecodable();
            malformedByTopic[topic]++;
            unusable(topic, MALFORMED, "malformed: " + e.getMessage());
            return;
        }
        if (scan) {
            if (scanValidator.acceptScan(scanScratch)) {
                usable(SCAN);
                scanEpochsSeen = noticeEpoch(scanValidator, scanEpochsSeen);
                laserOut.value().copyFrom(scanScratch);
                laserOut.publish();
                scans++;
                if (SampleAttachment.valid(sample.attachment(), sample.attachmentLength())) {
                    pendingScanSourceNs = SampleAttachment.sourceTimestampNs(sample.attachment());
                    latencySource = LATENCY_FROM_ATTACHMENT;
                } else if (wallClockStamp(header.stampNs)) {
                    // DDS through the bridge carries no source timestamp; a driver's wall-clock stamp stands in
                    pendingScanSourceNs = header.stampNs;
                    latencySource = LATENCY_FROM_HEADER;
                }
            } else {
                lastProblem = "scan: " + scanValidator.lastRejection();
                unusable(SCAN, IMPOSSIBLE, scanValidator.lastRejection());
            }
        } else if (odomValidator.acceptOdometry(odomScratch)) {
            usable(ODOM);
            odomEpochsSeen = noticeEpoch(odomValidator, odomEpochsSeen);
            odometryOut.value().copyFrom(odomScratch);
            odometryOut.publish();
            odometry++;
        } else {
            lastProblem = "odom: " + odomValidator.lastRejection();
            unusable(ODOM, IMPOSSIBLE, odomValidator.lastRejection());
        }
    }

    /** A topic's newest sample was committed: its streak of unusable ones, if any, is over. */
    private void usable(int topic) {
        (topic == SCAN ? scanTypes : odomTypes).usable();
        newestUnusable[topic] = false;
        unusableKinds[topic] = 0;
    }

    /** A topic's newest sample was dropped, as {@code kind}, for {@code why}. */
    private void unusable(int topic, int kind, String why) {
        newestUnusable[topic] = true;
        unusableKinds[topic] |= kind;
        unusableWhy[topic] = why;
    }

    /**
     * Whether a header stamp reads as a wall-clock time of now (within the last
     * {@link #MAX_LATENCY_NS} ns, or at most {@link #STAMP_AHEAD_NS} ns ahead): a driver's
     * acquisition time, not a simulated clock's.
     */
    private boolean wallClockStamp(long stampNs) {
        long ageNs = epoch.epochNanos() - stampNs;
        return ageNs >= -STAMP_AHEAD_NS && ageNs <= MAX_LATENCY_NS;
    }

    /** A notice that must reach the user while the run goes on: a warning of the library log too. */
    private void warn(String line) {
        notices.add(line);
        LOG.log(System.Logger.Level.WARNING, "ros2: " + line);
    }

    /** Reports a new epoch of the source's clock once; returns the epochs seen now. */
    private long noticeEpoch(SampleValidator validator, long seen) {
        long epochs = validator.clockEpochs();
        if (epochs != seen) {
            notices.add(validator.lastClockEpoch());
        }
        return epochs;
    }

    /**
     * Halts the robot when a topic has sent only unusable samples, malformed (they do not decode)
     * or impossible (they decode to values that cannot be true), for
     * {@link #IMPOSSIBLE_DATA_FAULT_AFTER_NS} of world time: acting on it would mean driving blind.
     */
    private void watchRejections(long nowNs) throws ZenohException, ImpossibleDataException {
        boolean scanFault = scanWatch.observe(nowNs, newestUnusable[SCAN]);
        boolean odomFault = odomWatch.observe(nowNs, newestUnusable[ODOM]);
        if (fault != null || !(scanFault || odomFault)) {
            return;
        }
        int topic = odomFault ? ODOM : SCAN;
        SampleValidator checks = odomFault ? odomValidator : scanValidator;
        long sinceNs = (odomFault ? odomWatch : scanWatch).rejectingSinceNs();
        String kinds = switch (unusableKinds[topic]) {
            case IMPOSSIBLE -> "impossible";
            case MALFORMED -> "malformed";
            default -> "malformed or impossible";
        };
        fault = String.format(Locale.ROOT, "ROS 2 topic %s sent only %s samples for %.1f s of world time (%d rejected as"
                        + " impossible, %d malformed in all), latest: %s; robot halted",
                odomFault ? topics.qualifiedOdom() : topics.qualifiedScan(), kinds, (nowNs - sinceNs) / 1e9,
                checks.rejected(), malformedByTopic[topic], unusableWhy[topic]);
        sendVelocity(zero, nowNs);
        throw new ImpossibleDataException(fault);
    }

    /**
     * @return why the robot was halted (one line naming the topic and the value), or null while
     *     the data can be trusted; once set, only zero velocities are sent until {@link #terminate}
     */
    public String fault() {
        return fault;
    }

    private void sendMotor(long nowNs) throws ZenohException {
        if (fault != null) {
            // halted: only zero velocities, again after the keep-alive period
            if (sentVxMps != 0.0 || sentOmegaRadPerSec != 0.0 || nowNs - sentAtNs >= keepAliveNs) {
                sendVelocity(zero, nowNs);
            }
            return;
        }
        if (motorIn.hasValue() && motorIn.generation() != motorGeneration) {
            motorGeneration = motorIn.generation();
            VelocityCommand cmd = motorIn.value();
            if (!commandSent || cmd.vxMps != sentVxMps || cmd.omegaRadPerSec != sentOmegaRadPerSec) {
                sendVelocity(cmd, nowNs);
                return;
            }
        }
        if (commandSent && (sentAtNs == Long.MIN_VALUE || nowNs - sentAtNs >= keepAliveNs)) {
            sendVelocity(motorIn.value(), nowNs);
        }
    }

    private void sendVelocity(VelocityCommand cmd, long nowNs) throws ZenohException {
        publishTwist(cmd);
        commandSent = true;
        sentVxMps = cmd.vxMps;
        sentOmegaRadPerSec = cmd.omegaRadPerSec;
        sentAtNs = nowNs;
    }

    private void publishTwist(VelocityCommand cmd) throws ZenohException {
        long nowEpochNs = epoch.epochNanos();
        twistCodec.encode(header.set(nowEpochNs, ""), cmd, writer);
        cmdVel.publish(writer.buffer(), writer.size(), nowEpochNs);
    }

    /**
     * @return true: this task commands the robot, so a stop terminates it (the zero Twist below)
     *     before it waits for the other tasks' last cycles
     */
    @Override
    public boolean stopsFirst() {
        return true;
    }

    /**
     * Stops the robot and leaves: publishes a zero Twist, then closes the session (which
     * undeclares the node, its subscriptions and its publisher).
     *
     * @throws IOException the first failure, after every step was attempted
     */
    @Override
    public void terminate() throws IOException {
        IOException first = null;
        if (cmdVel != null) {
            try {
                publishTwist(zero);
            } catch (ZenohException e) {
                first = e;
            }
        }
        try {
            context.close();
        } catch (ZenohException e) {
            first = first == null ? e : first;
        }
        if (first != null) {
            throw first;
        }
    }

    /** @return a snapshot of the counters */
    public Ros2Stats stats() {
        return new Ros2Stats(scans, odometry, cmdVel == null ? 0 : cmdVel.published(), malformed, oversized,
                scanValidator.rejected(), odomValidator.rejected(), overflowedSeen,
                scanPublishers.ignored() + odomPublishers.ignored(),
                scanValidator.clockEpochs() + odomValidator.clockEpochs(), lastProblem, scanValidator.droppedBeams());
    }

    /**
     * @return one line per event reported once, in order: another publisher on an input topic,
     *     a publisher followed after the previous one fell silent, a new epoch of a topic's
     *     clock (a snapshot; may be called from any thread)
     */
    public List<String> notices() {
        return List.copyOf(notices);
    }

    /**
     * @return a copy of the histogram of scan latencies: from a scan's source timestamp (the
     *     publisher's clock, epoch ns; {@link #latencySource()}) to the end of the cycle that
     *     committed it, in ns; exact once the task stopped, approximate while it runs
     */
    public Histogram latencySnapshot() {
        return scanLatencyNs.copy();
    }

    /**
     * @return where the scan latency was measured from ({@link #LATENCY_FROM_ATTACHMENT} or
     *     {@link #LATENCY_FROM_HEADER}, the last one used), or null when no scan had either (over
     *     DDS from a robot whose stamps are a simulated clock): then the latency is unknown
     */
    public String latencySource() {
        return latencySource;
    }

    /** @return CPU time spent in this task's cycles so far, in ns */
    public long cpuNs() {
        return cpuNs;
    }

    /** @return where the robot's data is */
    public Ros2Topics topics() {
        return topics;
    }
}
