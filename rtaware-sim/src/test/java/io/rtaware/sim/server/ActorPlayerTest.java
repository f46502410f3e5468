package io.rtaware.sim.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.player.client.PlayerClient;
import io.rtaware.player.client.PlayerClientOptions;
import io.rtaware.player.client.PlayerCounters;
import io.rtaware.player.client.PlayerNackException;
import io.rtaware.player.protocol.DeviceAddress;
import io.rtaware.player.protocol.Interfaces;
import io.rtaware.player.protocol.SimulationPose2d;
import io.rtaware.player.protocol.Subtypes;
import io.rtaware.robot.geometry.Point2d;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.sim.actor.ActorShape;
import io.rtaware.sim.actor.ActorSpec;
import io.rtaware.sim.world.LaserConfig;
import io.rtaware.sim.world.RobotModel;
import io.rtaware.sim.world.World;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Actors over the Player protocol, through the project's Player client as a controller would see
 * them: a person crossing and an obstacle appearing are in the laser scans at the world times the
 * scenario gives, and simulation:0 answers their poses as Stage answers for its models.
 */
class ActorPlayerTest {

    private static final long MS = 1_000_000L;

    @Test
    void aClientSeesActorsInItsScansAndTheirPosesThroughSimulation() throws Exception {
        // the paper room, the robot at (2, 1.5) facing +x: nothing within the laser's 4 m ahead or to the left
        ActorSpec person = new ActorSpec("person", ActorSpec.Kind.BODY, new ActorShape.Circle(0.25),
                List.of(new Point2d(3.0, 3.5), new Point2d(3.0, 0.3)), 1.0, ActorSpec.Repeat.ONCE, 1.0, 0, 0, 0);
        ActorSpec box = new ActorSpec("box", ActorSpec.Kind.OBSTACLE, new ActorShape.Box(0.4, 0.4),
                List.of(new Point2d(2.0, 2.6)), 0, ActorSpec.Repeat.ONCE, 0, 0, 0, 5.0);
        World world = new World(PlayerSimServerTest.ROOM.map().orElseThrow(), new Pose2d(2.0, 1.5, 0),
                RobotModel.ideal(0.1), LaserConfig.URG_04LX.withNoise(0), 1L, 1L, List.of(person, box));
        int ahead = LaserConfig.URG_04LX.beams() / 2;
        int left = ahead + (int) Math.round(Math.PI / 2 / LaserConfig.URG_04LX.angleIncrementRad());
        try (PlayerSimServer server = PlayerSimServer.startManual(world, ServerConfig.defaults(0));
             PlayerClient client = PlayerClient.connect("127.0.0.1", server.port(), PlayerClientOptions.defaults(),
                     new PlayerCounters())) {
            client.setDataMode(Subtypes.DATAMODE_PULL);
            client.subscribe(DeviceAddress.of(Interfaces.LASER, 0));
            step(server, 1000);
            client.requestData();
            client.poll(5000, true);
            assertEquals(LaserConfig.URG_04LX.maxRangeM(), client.laserScan().rangesM[ahead], 1e-5,
                    "1 s: nothing ahead within the laser's range");
            step(server, 2200);
            client.requestData();
            client.poll(5000, true);
            assertEquals(3.2, client.laserScan().serverTimeS, 1e-9);
            // at 3.2 s the person's centre is at (3.0, 1.3): the beam along y = 1.5 enters its 0.25 m circle at x = 3 - 0.15
            assertEquals(1.0 - Math.sqrt(0.25 * 0.25 - 0.2 * 0.2), client.laserScan().rangesM[ahead], 1e-6,
                    "3.2 s: the person crossing 1 m ahead");
            SimulationPose2d p = client.simulationPose2d(0, "person");
            assertEquals(3.0, p.xM(), 1e-12);
            assertEquals(3.5 - 2.2, p.yM(), 1e-9, "2.2 s after its start at 1.0 m/s");
            assertEquals(-Math.PI / 2, p.yawRad(), 1e-12, "heading along its motion");
            assertEquals(6.2 - 1.5, client.laserScan().rangesM[left], 1e-5,
                    "before 5 s: nothing to the left but the north wall, 4.7 m away");
            step(server, 2000);
            client.requestData();
            client.poll(5000, true);
            assertEquals(0.9, client.laserScan().rangesM[left], 1e-5, "5.2 s: the obstacle that appeared at 5 s, 0.9 m to the left");
            assertEquals(2.6, client.simulationPose2d(0, "box").yM(), 1e-12);
            assertThrows(PlayerNackException.class, () -> client.setSimulationPose2d(0, new SimulationPose2d("person", 0, 0, 0)),
                    "actors are not moved by clients");
        }
    }

    private static void step(PlayerSimServer server, int ms) {
        for (int i = 0; i < ms; i++) {
            server.step(MS);
        }
    }
}
