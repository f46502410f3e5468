package io.rtaware.ros2.graph;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.testing.Requires;
import io.rtaware.zenoh.DdsBridgeBuilt;
import io.rtaware.zenoh.ZenohException;
import io.rtaware.zenoh.ZenohSession;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A context on DDS asks its bridge's admin space (a Zenoh query, {@link ZenohSession#get}) within
 * its bounds: a count of replies and a size of one. DDS stays on loopback, multicast off, on a
 * domain of this test's own.
 */
@Timeout(60)
class Ros2ContextDdsTest {

    private static final int DOMAIN = 54;

    @Test
    @Requires(DdsBridgeBuilt.class)
    void theBridgesAdminSpaceAnswersWithinTheBoundsAndNobodyPublishesOnAnEmptyDomain() throws Exception {
        try (Ros2Context dds = Ros2Context.openDds(DdsSettings.loopback(DOMAIN, Ros2Distro.KILTED, Map.of()), 10_000)) {
            ZenohSession session = dds.session();
            List<ZenohSession.Reply> version = session.get("@/*/ros2/version", 2_000, 10, 64 * 1024);
            assertEquals(1, version.size(), version.toString());
            assertTrue(version.get(0).key().endsWith("/ros2/version") && !version.get(0).text().isEmpty(),
                    version.toString());
            ZenohException many = assertThrows(ZenohException.class, () -> session.get("@/*/ros2/**", 2_000, 1, 64 * 1024));
            assertEquals("more than 1 replies to '@/*/ros2/**'", many.getMessage());
            ZenohException large = assertThrows(ZenohException.class, () -> session.get("@/*/ros2/version", 2_000, 10, 4));
            assertTrue(large.getMessage().matches("a reply of \\d+ bytes to '@/\\*/ros2/version' exceeds the largest "
                    + "accepted \\(4\\)"), large.getMessage());
            assertThrows(IllegalArgumentException.class, () -> session.get("@/*/ros2/version", 2_000, -1, 4));
            assertEquals(Set.of(), dds.publishedTypes("/scan"), "nobody publishes rt/scan on domain " + DOMAIN);
            assertEquals("rt/scan", dds.wireName("/scan"));
        }
    }
}
