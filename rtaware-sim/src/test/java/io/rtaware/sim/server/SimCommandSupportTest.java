package io.rtaware.sim.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.time.ScaledClock;
import io.rtaware.player.protocol.Interfaces;
import io.rtaware.player.protocol.Subtypes;
import io.rtaware.robot.geometry.Point2d;
import io.rtaware.sim.scenario.Scenario;
import io.rtaware.sim.scenario.ScenarioLoader;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

class SimCommandSupportTest {

    @Test
    void scaledClockServerPublishesAtWorldTimeRates() throws Exception {
        ScaledClock clock = new ScaledClock(20.0);
        try (PlayerSimServer server = SimCommandSupport.start(ScenarioLoader.load("paper-room"), clock,
                ServerConfig.defaults(0), 5L, 5L);
             RawClient c = new RawClient(server.port())) {
            PlayerSimServerTest.dataMode(c, Subtypes.DATAMODE_PULL);
            PlayerSimServerTest.subscribe(c, Interfaces.POSITION2D);
            PlayerSimServerTest.subscribe(c, Interfaces.LASER);
            double firstS = -1;
            double lastS = 0;
            int odo = 0;
            int scans = 0;
            while (lastS - firstS < 6.0 || firstS < 0) {
                for (RawClient.Msg m : c.round()) {
                    double t = m.header().timestampS();
                    if (firstS < 0) {
                        firstS = t;
                    }
                    lastS = t;
                    if (m.header().interf() == Interfaces.POSITION2D) {
                        odo++;
                    } else {
                        scans++;
                    }
                }
            }
            double spanS = lastS - firstS;
            assertEquals(16.0, odo / spanS, 1.5, "odometry per world second");
            assertEquals(10.0, scans / spanS, 1.5, "scans per world second");
            assertTrue(server.simTimeS() >= lastS);
        }
    }

    @Test
    void scenarioWithoutMapIsRefused() {
        Scenario s = new Scenario("bare", Optional.empty(), io.rtaware.robot.geometry.Pose2d.ORIGIN,
                List.of(new Point2d(1, 1)), 0.3, 10);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> SimCommandSupport.start(s, new ScaledClock(1), ServerConfig.defaults(0), 1L, 1L));
        assertTrue(e.getMessage().contains("bare"));
    }

    @Test
    void configRejectsBadValuesNamingThem() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new ServerConfig("127.0.0.1", 70000, "r0", 10, 10_000_000L, 1024));
        assertTrue(e.getMessage().contains("port") && e.getMessage().contains("70000"));
        assertEquals("127.0.0.1", ServerConfig.defaults(0).bindAddress());
    }
}
