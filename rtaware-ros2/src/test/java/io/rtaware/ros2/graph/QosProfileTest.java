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

    @Test
    void depthMustBePositive() {
        assertThrows(IllegalArgumentException.class, () -> new QosProfile(true, false, 0));
    }
}
