package io.rtaware.player.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/**
 * What player-probe prints of a device's geometry and a ranger's configuration reads as domain
 * text (issue 34: {@code geometry Geometry[pose=Pose3d[xM=0.1, yM=0.0, ...], size=Bbox3d[...]]}).
 */
class DomainTextTest {

    @Test
    void geometryReadsAsAPlaceAndASize() {
        Geometry g = new Geometry(new Pose3d(0.1, 0, 0.2, 0, 0, Math.PI / 2), new Bbox3d(0.3, 0.3, 0.2));
        assertEquals("at (0.100, 0.000, 0.200) m, yaw 90.0 deg; size 0.30 x 0.30 x 0.20 m", g.toString());
        assertEquals("at (0.000, 0.000, 0.000) m, yaw 0.0 deg, roll 0.0 deg, pitch 90.0 deg",
                new Pose3d(0, 0, 0, 1e-300, Math.PI / 2, 0).toString(), "a tilted device says so");
    }

    @Test
    void rangerConfigReadsAsBeamsAndRanges() {
        RangerConfig c = new RangerConfig(-Math.PI / 2, Math.PI / 2, Math.toRadians(0.5), 0.02, 5.6, 0.001, 10);
        assertEquals("beams -90.0..90.0 deg every 0.500 deg, range 0.02..5.60 m (resolution 0.001 m), 10.0 Hz", c.toString());
    }
}
