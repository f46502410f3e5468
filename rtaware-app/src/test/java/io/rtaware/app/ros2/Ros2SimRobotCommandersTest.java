package io.rtaware.app.ros2;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.testing.Requires;
import io.rtaware.core.testing.Waits;
import io.rtaware.core.time.SystemClock;
import io.rtaware.robot.msg.VelocityCommand;
import io.rtaware.ros2.graph.QosProfile;
import io.rtaware.ros2.graph.Ros2Context;
import io.rtaware.ros2.graph.Ros2Publisher;
import io.rtaware.ros2msg.Ros2Header;
import io.rtaware.ros2msg.TwistCodec;
import io.rtaware.ros2msg.cdr.CdrWriter;
import io.rtaware.sim.ros2.Ros2SimRobot;
import io.rtaware.sim.scenario.ScenarioLoader;
import io.rtaware.sim.server.PlayerSimServer;
import io.rtaware.sim.server.ServerConfig;
import io.rtaware.sim.server.SimCommandSupport;
import io.rtaware.zenoh.NativeZenohLayer;
import io.rtaware.zenoh.ZenohConfig;
import java.net.ServerSocket;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A foreign velocity publisher on the simulated ROS 2 robot (issue 24, finding 7): only the first
 * {@code cmd_vel} publisher heard drives it; the other is reported once and its Twists dropped.
 */
@Timeout(120)
class Ros2SimRobotCommandersTest {

    private final TwistCodec codec = new TwistCodec();
    private final CdrWriter writer = new CdrWriter(256);
    private final Ros2Header header = new Ros2Header();

    private void send(Ros2Publisher publisher, double vxMps, double omegaRadPerSec) throws Exception {
        VelocityCommand command = new VelocityCommand();
        command.set(vxMps, omegaRadPerSec);
        codec.encode(header.set(System.currentTimeMillis() * 1_000_000L, ""), command, writer);
        publisher.publish(writer.buffer(), writer.size(), System.currentTimeMillis() * 1_000_000L);
    }

    @Test
    @Requires(NativeZenohLayer.class)
    void aForeignCmdVelPublisherIsReportedOnceAndDoesNotDriveTheRobot() throws Exception {
        String endpoint;
        try (ServerSocket s = new ServerSocket(0)) {
            endpoint = "tcp/127.0.0.1:" + s.getLocalPort();
        }
        List<String> reported = new CopyOnWriteArrayList<>();
        try (PlayerSimServer server = SimCommandSupport.start(ScenarioLoader.load("paper-room"), new SystemClock(),
                     ServerConfig.defaults(0), 1, 4);
             Ros2SimRobot robot = Ros2SimRobot.start(server,
                     Ros2Context.open(ZenohConfig.loopbackPeer().withListen(List.of(endpoint)), 0), "/", reported::add);
             Ros2Context controller = Ros2Context.open(ZenohConfig.loopbackPeer().withConnect(List.of(endpoint)), 0);
             Ros2Context intruder = Ros2Context.open(ZenohConfig.loopbackPeer().withConnect(List.of(endpoint)), 0)) {
            Ros2Publisher mine = controller.createNode("/", "controller")
                    .createPublisher("cmd_vel", codec.type(), QosProfile.defaults(), 256);
            Ros2Publisher theirs = intruder.createNode("/", "intruder")
                    .createPublisher("cmd_vel", codec.type(), QosProfile.defaults(), 256);
            Waits.until(() -> { // the subscription propagates asynchronously: send until one arrives
                send(mine, 0.1, 0.0);
                return robot.commands() > 0;
            }, Duration.ofSeconds(30), "the controller's Twist");
            Waits.until(() -> {
                send(mine, 0.1, 0.0);
                send(theirs, 0.5, 1.0);
                return robot.foreignCommands() >= 20;
            }, Duration.ofSeconds(30), () -> "20 of the intruder's Twists; reported " + reported);
            assertTrue(robot.commands() <= mine.published(), "only the controller's Twists are obeyed: "
                    + robot.commands() + " obeyed, " + mine.published() + " sent by the controller");
            assertEquals(1, reported.size(), "reported once: " + reported);
            assertTrue(reported.get(0).matches("/cmd_vel: another publisher \\(gid [0-9a-f]{32}\\) besides the one "
                    + "followed \\(gid [0-9a-f]{32}\\); its samples are dropped"), reported.get(0));
            assertEquals(reported, robot.notices());
        }
    }
}
