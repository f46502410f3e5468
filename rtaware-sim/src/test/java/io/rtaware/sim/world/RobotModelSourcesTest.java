package io.rtaware.sim.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.sim.map.OccupancyMap;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/**
 * Every parameter of the Koala and its URG-04LX says where it comes from, and the laser link
 * decides when scans arrive (measured on the world's stepped time).
 */
class RobotModelSourcesTest {

    private static final long MS = 1_000_000L;
    private static final List<String> KINDS = List.of("source:", "estimate:", "derived", "assumption:");

    @Test
    void everyReportedParameterHasASourceOrIsLabelledAnEstimate() {
        Map<String, String> sources = RobotModel.sources();
        sources.putAll(LaserConfig.urg04lxSources());
        List<String> keys = new ArrayList<>(RobotModel.koala(0.1).parameters().keySet());
        keys.addAll(LaserConfig.URG_04LX.parameters().keySet());
        keys.remove("name");
        for (String key : keys) {
            String source = sources.get(key);
            assertTrue(source != null, "no source for " + key);
            assertTrue(KINDS.stream().anyMatch(source::startsWith), key + " is neither sourced nor labelled: " + source);
        }
        assertEquals(keys.size(), sources.size(), "no source for a parameter that is not reported: " + sources.keySet());
    }

    @Test
    void theSerialLinkDeliversA124MillisecondTransferEverySecondTurn() {
        OccupancyMap.CellState[] cells = new OccupancyMap.CellState[100 * 100];
        Arrays.fill(cells, OccupancyMap.CellState.FREE);
        OccupancyMap empty = new OccupancyMap("empty", 100, 100, 0.1, -5, -5, cells);
        RobotModel serial = RobotModel.koala(0.1).withLaserLink(LaserTiming.Link.SERIAL);
        assertEquals("serial", serial.parameters().get("laser_link"));
        assertEquals(124.0, serial.parameters().get("laser_delivery_delay_ms"));
        World w = new World(empty, new Pose2d(0, 0, 0), serial, LaserConfig.URG_04LX, 1L);
        double beamNs = 100e6 * LaserConfig.URG_04LX.angleIncrementRad() / (2 * Math.PI);
        long deliveryNs = (long) (682 * beamNs) + 124 * MS;
        List<Long> fresh = new ArrayList<>();
        for (long t = MS; t <= 600 * MS; t += MS) {
            w.step(MS);
            if (w.scanFresh()) {
                fresh.add(t);
            }
        }
        long first = (deliveryNs / MS + 1) * MS;
        assertEquals(List.of(first, first + 200 * MS, first + 400 * MS), fresh,
                "190.6 ms after the first beam, then every second turn (5 Hz)");
        assertEquals(LaserTiming.Link.USB, RobotModel.koala(0.1).laserTiming().link(), "the Koala's profile assumes USB");
        assertThrows(IllegalArgumentException.class, () -> LaserTiming.Link.parse("wifi"));
    }
}
