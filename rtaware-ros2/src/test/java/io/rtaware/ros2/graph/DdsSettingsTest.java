package io.rtaware.ros2.graph;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.zenoh.DdsBridgeConfig;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class DdsSettingsTest {

    @TempDir
    Path dir;

    @Test
    void byDefaultDdsStaysOnLoopbackWithoutMulticast() {
        DdsSettings s = DdsSettings.loopback(7, Ros2Distro.KILTED, Map.of());
        assertTrue(s.confined());
        assertEquals("{\"domain\": 7, \"namespace\": \"/\", \"nodename\": \"rtaware_dds_bridge\", "
                + "\"ros_localhost_only\": false, \"ros_automatic_discovery_range\": \"SYSTEM_DEFAULT\"}", s.pluginConfig(),
                "the Cyclone DDS configuration is whole: the plugin adds nothing");
        String cyclone = s.cycloneConfig();
        assertTrue(cyclone.contains("<NetworkInterface name=\"lo\"/>"), cyclone);
        assertTrue(cyclone.contains("<AllowMulticast>false</AllowMulticast>"), cyclone);
        assertTrue(cyclone.contains("<Peer address=\"127.0.0.1\"/>"), cyclone);
        assertTrue(cyclone.contains("<ParticipantIndex>auto</ParticipantIndex>"), cyclone);
        assertEquals("lo", s.bindInterface(), "the bridge's sockets are held to lo");
        assertEquals(Map.of("ROS_DISTRO", "kilted"), s.environment());
        DdsBridgeConfig bridge = s.bridgeConfig("tcp/127.0.0.1:0");
        assertEquals(List.of(s.pluginConfig(), cyclone, "lo", s.environment()),
                List.of(bridge.pluginConfig(), bridge.cycloneConfig(), bridge.bindInterface(), bridge.environment()));
        assertEquals("DDS domain 7 (loopback only, no multicast) through zenoh-plugin-ros2dds", s.describe());
    }

    @Test
    void humbleHasNoDiscoveryRangeAndUsesLocalhostOnly() {
        DdsSettings s = DdsSettings.loopback(0, Ros2Distro.HUMBLE, Map.of());
        assertEquals("{\"domain\": 0, \"namespace\": \"/\", \"nodename\": \"rtaware_dds_bridge\", "
                + "\"ros_localhost_only\": false}", s.pluginConfig());
        assertEquals("humble", s.environment().get("ROS_DISTRO"));
        assertTrue(s.cycloneConfig().contains("<Peer address=\"127.0.0.1\"/>"), s.cycloneConfig());
    }

    @Test
    void anotherInterfaceOpensDdsToItsNetworkWithMulticastDiscovery() {
        DdsSettings s = new DdsSettings(3, Ros2Distro.JAZZY, "eth0", null);
        assertFalse(s.confined());
        String cyclone = s.cycloneConfig();
        assertTrue(cyclone.contains("<NetworkInterface name=\"eth0\"/>"), cyclone);
        assertFalse(cyclone.contains("AllowMulticast"), cyclone);
        assertFalse(cyclone.contains("Peer address"), cyclone);
        assertTrue(cyclone.contains("<MaxAutoParticipantIndex>32</MaxAutoParticipantIndex>"), "as ROS 2's SUBNET range: " + cyclone);
        assertEquals("eth0", s.bindInterface());
        assertFalse(new DdsSettings(3, Ros2Distro.HUMBLE, "eth0", null).cycloneConfig().contains("ParticipantIndex"),
                "Humble's Cyclone DDS defaults");
    }

    @Test
    void aUsersCycloneConfigurationIsUsedAsItIsAndThePluginAddsNothing() throws Exception {
        Path file = Files.writeString(dir.resolve("cyclone.xml"), "<CycloneDDS/>");
        String uri = file.toUri().toString();
        DdsSettings s = DdsSettings.loopback(0, Ros2Distro.KILTED, Map.of("CYCLONEDDS_URI", uri));
        assertFalse(s.confined());
        assertEquals(uri, s.cycloneConfig());
        assertNull(s.bindInterface(), "Cyclone DDS binds as the user's configuration makes it");
        assertTrue(s.pluginConfig().contains("\"SYSTEM_DEFAULT\""), s.pluginConfig());
        assertEquals("DDS domain 0 (configured by CYCLONEDDS_URI) through zenoh-plugin-ros2dds", s.describe());
        DdsSettings inline = DdsSettings.loopback(0, Ros2Distro.KILTED, Map.of("CYCLONEDDS_URI", "<CycloneDDS/>"));
        assertEquals("<CycloneDDS/>", inline.cycloneConfig(), "inline XML is left to Cyclone DDS");
        assertEquals(file.toString(), DdsSettings.loopback(0, Ros2Distro.KILTED,
                Map.of("CYCLONEDDS_URI", file.toString())).userCycloneUri(), "a plain path");
    }

    @Test
    void badSettingsNameTheValue() {
        Path missing = dir.resolve("missing.xml");
        IllegalArgumentException unreadable = assertThrows(IllegalArgumentException.class,
                () -> DdsSettings.loopback(0, Ros2Distro.KILTED, Map.of("CYCLONEDDS_URI", "file://" + missing)));
        assertEquals("CYCLONEDDS_URI: cannot read 'file://" + missing + "'", unreadable.getMessage());
        assertEquals("ROS domain id must be 0..232, got 233", assertThrows(IllegalArgumentException.class,
                () -> DdsSettings.loopback(233, Ros2Distro.KILTED, Map.of())).getMessage());
        assertEquals("malformed network interface name 'eth0; rm'", assertThrows(IllegalArgumentException.class,
                () -> new DdsSettings(0, Ros2Distro.KILTED, "eth0; rm", null)).getMessage());
    }
}
