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
 * loopback endpoint with a node that publishes {@code /scan} (every beam 4 m) and {@code /odom}
 * (the pose integrated from the Twists it receives on {@code /cmd_vel}) every 20 ms of wall
 * time, and, once it has been driven for {@code poisonAfterMs} of wall time, odometry whose x is
 * NaN from then on. Its own thread publishes; {@link #close()} stops it.
 */
final class NanPoseRos2Robot implements AutoCloseable {

    private static final long TICK_NS = TimeUnit.MILLISECONDS.toNanos(20);

    private final Ros2Context context;
    private final Ros2Publisher scanPub;
    private final Ros2Publisher odomPub;
    private final ZenohMailbox cmdVel;
    private final long poisonAfterNs;
    private final Thread thread;
    private final LaserScan scan = new LaserScan(181);
    private final Odometry odom = new Odometry();
    private final VelocityCommand command = new VelocityCommand();
    private volatile boolean running = true;
    private volatile boolean drove;
    private volatile boolean poisoned;
    private volatile VelocityCommand lastTwist;
    private volatile Exception failure;

    NanPoseRos2Robot(String listenEndpoint, long poisonAfterMs) throws ZenohException {
        context = Ros2Context.open(ZenohConfig.loopbackPeer().withListen(List.of(listenEndpoint)), 0);
        Ros2Node node = context.createNode("/", "nan_pose_robot");
        scanPub = node.createPublisher("/scan", Ros2Types.LASER_SCAN, QosProfile.sensorData(), 64 * 1024);
        odomPub = node.createPublisher("/odom", Ros2Types.ODOMETRY, QosProfile.defaults(), 64 * 1024);
        cmdVel = context.session().newMailbox(64);
        node.subscribe("/cmd_vel", Ros2Types.TWIST, QosProfile.defaults(), cmdVel, 0);
        poisonAfterNs = TimeUnit.MILLISECONDS.toNanos(poisonAfterMs);
        scan.setCount(181);
        scan.minAngleRad = -Math.PI / 2;
        scan.maxAngleRad = Math.PI / 2;
        scan.maxRangeM = 8;
        Arrays.fill(scan.rangesM, 0, 181, 4f);
        odom.xM = 0.8;
        odom.yM = 0.8;
        thread = new Thread(this::loop, "nan-pose-robot");
        thread.setDaemon(true);
        thread.start();
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
                scan.serverTimeS = stampNs / 1e9;
                scanCodec.encode(header.set(stampNs, "laser"), scan, writer);
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
