package io.rtaware.app.ros2;

import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.robot.msg.VelocityCommand;
import io.rtaware.ros2.graph.QosProfile;
import io.rtaware.ros2.graph.Ros2Context;
import io.rtaware.ros2.graph.Ros2Node;
import io.rtaware.ros2.graph.Ros2Publisher;
import io.rtaware.ros2msg.LaserScanCodec;
import io.rtaware.ros2msg.OdometryCodec;
import io.rtaware.ros2msg.Ros2Header;
import io.rtaware.ros2msg.Ros2Types;
import io.rtaware.ros2msg.TwistCodec;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.cdr.CdrWriter;
import io.rtaware.zenoh.SampleBuffer;
import io.rtaware.zenoh.ZenohConfig;
import io.rtaware.zenoh.ZenohException;
import io.rtaware.zenoh.ZenohMailbox;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * A ROS 2 robot for tests, built on rtaware's own ROS 2 layer: a Zenoh peer listening on a
 * loopback endpoint with a node that publishes {@code /scan} (181 beams over a half turn, each
 * reading what the test says, 4 m by default) and {@code /odom} (the pose integrated from the
 * Twists it receives on {@code /cmd_vel}) every 20 ms of wall time; optionally, once it has been
 * driven for a while, odometry whose x is NaN from then on. Its own thread publishes;
 * {@link #close()} stops it.
 */
final class ScriptedRos2Robot implements AutoCloseable {

    private static final long TICK_NS = TimeUnit.MILLISECONDS.toNanos(20);

    private final Ros2Context context;
    private final Ros2Publisher scanPub;
    private final Ros2Publisher odomPub;
    private final ZenohMailbox cmdVel;
    private final long poisonAfterNs;
    private final Thread thread;
    private final LaserScan scan = new LaserScan(181);
    private final long scanStampAheadNs;
    private volatile float maxForwardMps;
    private final Odometry odom = new Odometry();
    private final VelocityCommand command = new VelocityCommand();
    private volatile boolean running = true;
    private volatile boolean drove;
    private volatile boolean poisoned;
    private volatile VelocityCommand lastTwist;
    private volatile Exception failure;

    /**
     * @param listenEndpoint where its Zenoh peer listens
     * @param poisonAfterMs wall time of driving after which its odometry is NaN, or
     *     {@link Long#MAX_VALUE} for never
     * @param beams beams per scan, 0 to 181
     * @param rangeM every beam's reading, metres (infinities as REP 117 uses them)
     * @param scanStampAheadNs how far ahead of its clock the scans are stamped
     */
    private ScriptedRos2Robot(String listenEndpoint, long poisonAfterMs, int beams, float rangeM, long scanStampAheadNs)
            throws ZenohException {
        context = Ros2Context.open(ZenohConfig.loopbackPeer().withListen(List.of(listenEndpoint)), 0);
        Ros2Node node = context.createNode("/", "scripted_robot");
        scanPub = node.createPublisher("/scan", Ros2Types.LASER_SCAN, QosProfile.sensorData(), 64 * 1024);
        odomPub = node.createPublisher("/odom", Ros2Types.ODOMETRY, QosProfile.defaults(), 64 * 1024);
        cmdVel = context.session().newMailbox(64);
        node.subscribe("/cmd_vel", Ros2Types.TWIST, QosProfile.defaults(), cmdVel, 0);
        poisonAfterNs = poisonAfterMs == Long.MAX_VALUE ? Long.MAX_VALUE : TimeUnit.MILLISECONDS.toNanos(poisonAfterMs);
        this.scanStampAheadNs = scanStampAheadNs;
        scan.setCount(beams);
        scan.minAngleRad = -Math.PI / 2;
        scan.maxAngleRad = Math.PI / 2;
        scan.minRangeM = 0.02;
        scan.maxRangeM = 8;
        Arrays.fill(scan.rangesM, 0, beams, rangeM);
        odom.xM = 0.8;
        odom.yM = 0.8;
        thread = new Thread(this::loop, "scripted-ros2-robot");
        thread.setDaemon(true);
        thread.start();
    }

    /** A robot whose scans are true (every beam 4 m) and whose odometry turns NaN once driven for a while. */
    static ScriptedRos2Robot nanPosesAfter(String listenEndpoint, long poisonAfterMs) throws ZenohException {
        return new ScriptedRos2Robot(listenEndpoint, poisonAfterMs, 181, 4f, 0);
    }

    /** A robot with true odometry whose scans have {@code beams} beams, each reading {@code rangeM}. */
    static ScriptedRos2Robot scanning(String listenEndpoint, int beams, float rangeM, long stampAheadNs)
            throws ZenohException {
        return new ScriptedRos2Robot(listenEndpoint, Long.MAX_VALUE, beams, rangeM, stampAheadNs);
    }

    private void loop() {
        SampleBuffer sample = new SampleBuffer(4096, 64);
        CdrWriter writer = new CdrWriter(64 * 1024);
        CdrReader reader = new CdrReader();
        Ros2Header header = new Ros2Header();
        LaserScanCodec scanCodec = new LaserScanCodec();
        OdometryCodec odomCodec = new OdometryCodec("base_link");
        TwistCodec twistCodec = new TwistCodec();
        long startNs = System.nanoTime();
        long droveSinceNs = Long.MIN_VALUE;
        long nextTickNs = startNs;
        try {
            while (running) {
                // The mailbox's wait paces the robot: Twists are taken as they come, a tick every 20 ms.
                ZenohMailbox.Take took = cmdVel.take(Math.max(0, nextTickNs - System.nanoTime()), sample);
                if (took == ZenohMailbox.Take.SAMPLE) {
                    byte[] bytes = new byte[sample.payloadLength()];
                    sample.payload().get(0, bytes);
                    VelocityCommand v = new VelocityCommand();
                    twistCodec.decode(reader.wrap(bytes, 0, bytes.length), header, v);
                    command.set(v.vxMps, v.omegaRadPerSec);
                    lastTwist = v;
                    maxForwardMps = Math.max(maxForwardMps, (float) v.vxMps);
                    if (!v.isStop() && !drove) {
                        drove = true;
                        droveSinceNs = System.nanoTime();
                    }
                    continue;
                }
                if (took == ZenohMailbox.Take.CLOSED) {
                    return;
                }
                long nowNs = System.nanoTime();
                nextTickNs = nowNs + TICK_NS;
                double dtS = TICK_NS / 1e9;
                odom.yawRad += command.omegaRadPerSec * dtS;
                odom.xM += command.vxMps * Math.cos(odom.yawRad) * dtS;
                odom.yM += command.vxMps * Math.sin(odom.yawRad) * dtS;
                odom.vxMps = command.vxMps;
                odom.omegaRadPerSec = command.omegaRadPerSec;
                long stampNs = nowNs - startNs;
                scan.serverTimeS = (stampNs + scanStampAheadNs) / 1e9;
                scanCodec.encode(header.set(stampNs + scanStampAheadNs, "laser"), scan, writer);
                scanPub.publish(writer.buffer(), writer.size(), System.currentTimeMillis() * 1_000_000L);
                poisoned |= drove && nowNs - droveSinceNs >= poisonAfterNs;
                double trueX = odom.xM;
                if (poisoned) {
                    odom.xM = Double.NaN;
                }
                odomCodec.encode(header.set(stampNs, "odom"), odom, writer);
                odom.xM = trueX;
                odomPub.publish(writer.buffer(), writer.size(), System.currentTimeMillis() * 1_000_000L);
            }
        } catch (Exception e) {
            failure = e;
        }
    }

    /** @return true once a non-zero Twist was received */
    boolean drove() {
        return drove;
    }

    /** @return the fastest forward speed it was ever commanded, m/s */
    float maxForwardMps() {
        return maxForwardMps;
    }

    /** @return the distance it drove from its start, metres (its odometry is exact) */
    double distanceFromStartM() {
        return Math.hypot(odom.xM - 0.8, odom.yM - 0.8);
    }

    /** @return true once it sends NaN poses */
    boolean poisoned() {
        return poisoned;
    }

    /** @return the newest Twist received, or null */
    VelocityCommand lastTwist() {
        return lastTwist;
    }

    /** @return what stopped the robot's thread, or null */
    Exception failure() {
        return failure;
    }

    @Override
    public void close() throws Exception {
        running = false;
        thread.join(10_000);
        context.close();
    }
}
