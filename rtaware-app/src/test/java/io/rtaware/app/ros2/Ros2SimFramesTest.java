package io.rtaware.app.ros2;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.testing.Requires;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.ros2.graph.QosProfile;
import io.rtaware.ros2.graph.Ros2Context;
import io.rtaware.ros2.graph.Ros2Node;
import io.rtaware.ros2msg.OdometryCodec;
import io.rtaware.ros2msg.Ros2Header;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.sim.ros2.Ros2SimRobot;
import io.rtaware.sim.scenario.ScenarioLoader;
import io.rtaware.sim.server.PlayerSimServer;
import io.rtaware.sim.server.ServerConfig;
import io.rtaware.sim.world.LaserConfig;
import io.rtaware.sim.world.RobotModel;
import io.rtaware.sim.world.World;
import io.rtaware.zenoh.NativeZenohLayer;
import io.rtaware.zenoh.SampleBuffer;
import io.rtaware.zenoh.ZenohConfig;
import io.rtaware.zenoh.ZenohMailbox;
import java.net.ServerSocket;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * {@code sim --ros2} names its frames as recordings do (REP 105, one meaning per name): odometry
 * in {@code odom}, the true pose in the world's fixed frame {@code world} (it was {@code map},
 * the name recordings also gave the controller's odometry-based map).
 */
@Timeout(120)
class Ros2SimFramesTest {

    private static final long MS = 1_000_000L;

    @Test
    @Requires(NativeZenohLayer.class)
    void groundTruthIsInTheWorldFrameAndOdometryInOdom() throws Exception {
        String endpoint;
        try (ServerSocket s = new ServerSocket(0)) {
            endpoint = "tcp/127.0.0.1:" + s.getLocalPort();
        }
        World world = new World(ScenarioLoader.load("paper-room").map().orElseThrow(), new Pose2d(2.0, 1.5, 0),
                RobotModel.ideal(0.1), LaserConfig.URG_04LX.withNoise(0), 1L, 1L, List.of());
        try (PlayerSimServer server = PlayerSimServer.startManual(world, ServerConfig.defaults(0));
             Ros2SimRobot robot = Ros2SimRobot.start(server,
                     Ros2Context.open(ZenohConfig.loopbackPeer().withListen(List.of(endpoint)), 0), "/", line -> { });
             Ros2Context watcher = Ros2Context.open(ZenohConfig.loopbackPeer().withConnect(List.of(endpoint)), 0)) {
            Ros2Node node = watcher.createNode("/", "frame_watcher");
            OdometryCodec codec = new OdometryCodec("base_link");
            ZenohMailbox truth = watcher.session().newMailbox(64);
            ZenohMailbox odom = watcher.session().newMailbox(64);
            node.subscribe("/" + Ros2SimRobot.GROUND_TRUTH, codec.type(), QosProfile.defaults(), truth, 0);
            node.subscribe("/" + Ros2SimRobot.ODOM, codec.type(), QosProfile.defaults(), odom, 0);
            assertEquals("world", frameOfFirst(truth, codec, server), "the true pose's frame");
            assertEquals("odom", frameOfFirst(odom, codec, server), "odometry's frame");
        }
    }

    /** Steps the world until the mailbox has a sample; returns its header's frame. */
    private static String frameOfFirst(ZenohMailbox mailbox, OdometryCodec codec, PlayerSimServer server)
            throws Exception {
        SampleBuffer sample = new SampleBuffer(1 << 12, 64);
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (mailbox.take(TimeUnit.MILLISECONDS.toNanos(200), sample) != ZenohMailbox.Take.SAMPLE) {
            assertTrue(System.nanoTime() < deadline, "a sample from the simulator's ROS 2 side");
            for (int i = 0; i < 100; i++) {
                server.step(MS);
            }
        }
        byte[] bytes = new byte[sample.payloadLength()];
        sample.payload().get(0, bytes, 0, bytes.length);
        Ros2Header header = new Ros2Header();
        codec.decode(new CdrReader().wrap(bytes, 0, bytes.length), header, new Odometry());
        return header.frameId.toString();
    }
}
