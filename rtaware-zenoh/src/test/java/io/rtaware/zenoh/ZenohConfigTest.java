package io.rtaware.zenoh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

class ZenohConfigTest {

    @Test
    void defaultsListenOnLoopbackOnlyWithoutScouting() {
        ZenohConfig c = ZenohConfig.loopbackPeer();
        assertEquals(List.of("tcp/127.0.0.1:0"), c.listen());
        assertFalse(c.multicastScouting(), "multicast scouting must be off by default");
        assertTrue(c.connect().isEmpty());
    }

    @Test
    void malformedEndpointsAreRejectedWithTheirText() {
        for (String bad : List.of("127.0.0.1:7447", "udp/127.0.0.1:7447", "tcp/127.0.0.1", "tcp/:7447",
                "tcp/host:70000", "tcp/host:7447/extra")) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> ZenohConfig.loopbackPeer().withConnect(List.of(bad)), bad);
            assertTrue(e.getMessage().contains("'" + bad + "'"), e.getMessage());
        }
    }

    @Test
    void portZeroIsOnlyForListening() {
        assertThrows(IllegalArgumentException.class, () -> ZenohConfig.loopbackPeer().withConnect(List.of("tcp/h:0")));
        assertEquals("tcp/[::1]:0", ZenohConfig.checkEndpoint("tcp/[::1]:0", true));
    }

    @Test
    void aClientNeedsARouter() {
        assertThrows(IllegalArgumentException.class,
                () -> new ZenohConfig(ZenohConfig.Mode.CLIENT, List.of(), List.of(), false, 1000));
    }
}
