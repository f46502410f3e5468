package io.rtaware.app.ros2;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.testing.Requires;
import io.rtaware.core.testing.Waits;
import io.rtaware.robot.geometry.Point2d;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.ros2.graph.QosProfile;
import io.rtaware.ros2.graph.Ros2Context;
import io.rtaware.ros2.graph.Ros2Node;
import io.rtaware.ros2msg.LaserScanCodec;
import io.rtaware.ros2msg.Ros2Header;
import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.sim.actor.ActorShape;
import io.rtaware.sim.actor.ActorSpec;
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
import java.time.Duration;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Actors in the simulated ROS 2 robot's {@code /scan}, as a ROS 2 node sees them (issue 27): an
 * obstacle that appears at 5 s of world time is absent from every scan measured before it and
 * present, at its exact range, in every scan from then on. The world is stepped by the test (no
 * wall-clock timing); the scans travel over Zenoh on loopback as CDR {@code sensor_msgs/msg/LaserScan}.
 */
@Timeout(120)
class Ros2ActorScanTest {

    private static final long MS = 1_000_000L;
    private static final double APPEAR_S = 5.0;

    @Test
    @Requires(NativeZenohLayer.class)
    void anObstacleThatAppearsIsInTheRos2ScansFromItsTimeOn() throws Exception {
        String endpoint;
        try (ServerSocket s = new ServerSocket(0)) {
            endpoint = "tcp/127.0.0.1:" + s.getLocalPort();
        }
        // The paper room, the robot at (2, 1.5) facing +x: to its left only the room's far wall, 4.7 m
        // away (within the laser's 5.6 m), until a 0.4 m box appears at (2, 2.6) at 5 s, its near face
        // 0.9 m away (5 s leave the subscription time to reach the robot before it).
        ActorSpec box = new ActorSpec("box", ActorSpec.Kind.OBSTACLE, new ActorShape.Box(0.4, 0.4),
                List.of(new Point2d(2.0, 2.6)), 0, ActorSpec.Repeat.ONCE, 0, 0, 0, APPEAR_S);
        World world = new World(ScenarioLoader.load("paper-room").map().orElseThrow(), new Pose2d(2.0, 1.5, 0),
                RobotModel.ideal(0.1), LaserConfig.URG_04LX.withNoise(0), 1L, 1L, List.of(box));
        int left = LaserConfig.URG_04LX.beams() / 2
                + (int) Math.round(Math.PI / 2 / LaserConfig.URG_04LX.angleIncrementRad());
        LaserScanCodec codec = new LaserScanCodec();
        LaserScan scan = new LaserScan();
        SampleBuffer sample = new SampleBuffer(1 << 16, 64);
        byte[] bytes = new byte[1 << 16];
        int[] before = {0};
        int[] after = {0};
        try (PlayerSimServer server = PlayerSimServer.startManual(world, ServerConfig.defaults(0));
             Ros2SimRobot robot = Ros2SimRobot.start(server,
                     Ros2Context.open(ZenohConfig.loopbackPeer().withListen(List.of(endpoint)), 0), "/", line -> { });
             Ros2Context watcher = Ros2Context.open(ZenohConfig.loopbackPeer().withConnect(List.of(endpoint)), 0)) {
            Ros2Node node = watcher.createNode("/", "scan_watcher");
            ZenohMailbox mailbox = watcher.session().newMailbox(64);
            node.subscribe("/scan", codec.type(), QosProfile.sensorData(), mailbox, 0);
            Waits.until(() -> {
                for (int i = 0; i < 100; i++) {
                    server.step(MS); // one laser period (10 Hz) of world time
                }
                if (mailbox.take(TimeUnit.MILLISECONDS.toNanos(200), sample) != ZenohMailbox.Take.SAMPLE) {
                    return false;
                }
                int n = sample.payloadLength();
                sample.payload().get(0, bytes, 0, n);
                codec.decode(new CdrReader().wrap(bytes, 0, n), new Ros2Header(), scan);
                if (scan.serverTimeS < APPEAR_S - 1e-9) {
                    before[0]++;
                    assertEquals(4.7, scan.rangesM[left], 1e-5, "at " + scan.serverTimeS + " s, before the box appears");
                } else {
                    after[0]++;
                    assertEquals(0.9, scan.rangesM[left], 1e-5, "at " + scan.serverTimeS + " s, the box 0.9 m to the left");
                }
                return after[0] >= 3;
            }, Duration.ofSeconds(60), () -> "three scans from the ROS 2 robot after 5 s: " + before[0] + " before, "
                    + after[0] + " after; published " + robot.scansPublished());
        }
        assertTrue(before[0] > 0, "at least one scan from before the box appeared");
    }
}
