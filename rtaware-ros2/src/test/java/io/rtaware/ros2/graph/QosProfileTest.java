package io.rtaware.ros2.graph;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class QosProfileTest {

    @Test
    void theDefaultProfileIsWrittenAsInRmwZenoh() {
        assertEquals("::,10:,:,:,,", QosProfile.defaults().tokenText());
        assertEquals("::,7:,:,:,,", new QosProfile(true, false, 7).tokenText(), "the design document's keep-last 7");
    }

    @Test
    void nonDefaultPoliciesCarryRmwEnumerationValues() {
        assertEquals("2::,5:,:,:,,", QosProfile.sensorData().tokenText());
        assertEquals(":1:,1:,:,:,,", new QosProfile(true, true, 1).tokenText());
    }

    /**
     * The text zenoh-plugin-ros2dds 1.10.2 writes in a route announcement
     * ({@code liveliness_mgt.rs}, {@code qos_to_key_expr}): keyless, then Cyclone DDS's values of
     * reliability, durability and history with its depth.
     */
    @Test
    void theBridgeTextCarriesCycloneDdsEnumerationValues() {
        assertEquals(":1:0:0,10", QosProfile.defaults().bridgeText(), "reliable, volatile, keep last 10");
        assertEquals(":0:0:0,5", QosProfile.sensorData().bridgeText(), "best effort, volatile, keep last 5");
        assertEquals(":1:1:0,1", new QosProfile(true, true, 1).bridgeText(), "transient local, as /tf_static");
    }

    @Test
    void depthMustBePositive() {
        assertThrows(IllegalArgumentException.class, () -> new QosProfile(true, false, 0));
    }
}
