package io.rtaware.nav;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.robot.geometry.Point2d;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The controller's configuration survives a recording's metadata exactly; other periods derive the rest again. */
class ControllerMetadataTest {

    private static final long MS = 1_000_000L;

    private static NavConfig config() {
        return NavConfig.builder().waypoints(List.of(new Point2d(1, 2), new Point2d(3.5, -1)))
                .grid(0.1, -2, -3, 12, 9).topSpeedMps(0.3).inflationMarginM(0.05)
                .periodsNs(Map.of("obstacle", 20 * MS, "planner", 250 * MS)).build();
    }

    @Test
    void theRecordedConfigurationIsReadBackEqual() {
        NavConfig config = config();
        Map<String, String> entries = ControllerMetadata.entries(config, "koala", 2);

        assertEquals(config, ControllerMetadata.navConfig(ControllerMetadata.configuration(config)));
        assertEquals("koala", entries.get("robot_model"));
        assertEquals("2", entries.get(ControllerMetadata.CORES));
        assertEquals("1.0,2.0 3.5,-1.0", entries.get("waypoints"));
    }

    @Test
    void otherPeriodsDeriveTheMediatorAgainAndKeepTheRest() {
        NavConfig recorded = config();
        NavConfig replayed = ControllerMetadata.withPeriods(recorded, Map.of("obstacle", 80 * MS));

        assertEquals(80 * MS, replayed.periodNs("obstacle"));
        assertEquals(250 * MS, replayed.periodNs("planner"), "a period not asked for stays as recorded");
        assertNotEquals(recorded.periods().mediatorNs(), replayed.periods().mediatorNs());
        assertEquals(recorded.grid(), replayed.grid());
        assertEquals(recorded.robot(), replayed.robot());
        assertEquals(recorded.course(), replayed.course());
        assertEquals(recorded, ControllerMetadata.withPeriods(recorded, Map.of()), "no change asked: the same");
    }

    @Test
    void aPeriodOfATaskOfNoSuchNameIsRefusedAndTheMediatorsIsKept() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ControllerMetadata.withPeriods(config(), Map.of("planer", 10 * MS)));
        assertTrue(e.getMessage().contains("unknown task 'planer'"), e.getMessage());
        assertEquals(10 * MS, ControllerMetadata.withPeriods(config(), Map.of("mediator", 10 * MS)).periods().mediatorNs(),
                "a mediator period named (as the period advice names it) is kept, not derived");
    }

    @Test
    void aRecordingWithoutTheControllerSaysSo() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ControllerMetadata.navConfig(Map.of("scenario", "paper-room")));
        assertTrue(e.getMessage().contains("no " + ControllerMetadata.NAV_CONFIG), e.getMessage());
        e = assertThrows(IllegalArgumentException.class,
                () -> ControllerMetadata.navConfig(Map.of(ControllerMetadata.NAV_CONFIG, "{not json")));
        assertTrue(e.getMessage().contains("not readable"), e.getMessage());
    }
}
