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
import io.rtaware.robot.msg.LaserScan;
import org.junit.jupiter.api.Test;

/** The rtaware-player client drives the simulator over a socket (manual world stepping). */
class PlayerClientEndToEndTest {

    @Test
    void clientSubscribesReadsDrivesAndReadsGroundTruth() throws Exception {
        try (PlayerSimServer server = PlayerSimServer.startManual(PlayerSimServerTest.world(), ServerConfig.defaults(0));
             PlayerClient client = PlayerClient.connect("127.0.0.1", server.port(), PlayerClientOptions.defaults(),
                     new PlayerCounters())) {
            assertEquals(PlayerSimServer.VERSION, client.serverVersion());
            client.setDataMode(Subtypes.DATAMODE_PULL);
            assertEquals(4, client.deviceList().size());
            client.subscribe(DeviceAddress.of(Interfaces.POSITION2D, 0));
            client.subscribe(DeviceAddress.of(Interfaces.LASER, 0));
            assertThrows(PlayerNackException.class, () -> client.subscribe(DeviceAddress.of(Interfaces.PLANNER, 0)));
            assertEquals(0.4, client.position2dGeometry(0).size().widthM(), 1e-12);
            assertEquals(683 - 1, Math.round((client.laserConfig(0).maxAngleRad() - client.laserConfig(0).minAngleRad())
                    / client.laserConfig(0).resolutionRad()));

            client.sendVelocity(0, 0.1, 0.0, 0.0, 1);
            client.deviceList(); // a request round trip: the command has been read by now
            for (int i = 0; i < 500; i++) {
                server.step(10_000_000L);
            }
            client.requestData();
            client.poll(5000, true);
            assertEquals(80, client.odometryUpdates(), "16 Hz over 5 s of world time");
            assertEquals(50, client.laserUpdates(), "10 Hz over 5 s of world time");
            assertEquals(0.8 + 0.5 - 0.01, client.odometry().xM, 0.002);
            assertEquals(5.0, client.odometry().serverTimeS, 1e-9);
            LaserScan scan = client.laserScan();
            assertEquals(683, scan.count());
            // facing +x from (1.29, 0.8): the pillar's west face at x = 4.8 is 3.51 m ahead
            assertEquals(4.8 - client.odometry().xM, scan.rangesM[341], 0.05);

            SimulationPose2d truth = client.simulationPose2d(0, "r0");
            assertEquals(server.groundTruth().xM(), truth.xM(), 1e-12);
            client.setSimulationPose2d(0, new SimulationPose2d("r0", 3.0, 1.5, 0.0));
            assertEquals(3.0, client.simulationPose2d(0, "r0").xM(), 1e-12);
            assertTrue(server.clientCount() >= 1);
        }
    }
}
