package io.rtaware.ros2.graph;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import io.rtaware.ros2msg.Ros2Types;
import org.junit.jupiter.api.Test;

/**
 * What each {@code --ros-distro} value changes, as exact strings: Humble's rmw_zenoh writes
 * {@code TypeHashNotSupported} where Jazzy, Kilted and Rolling write the RIHS01 hash, in the
 * topic key expression as in the liveliness token.
 */
class Ros2DistroTest {

    private static final String TWIST = "geometry_msgs::msg::dds_::Twist_";
    private static final String TWIST_HASH = "RIHS01_9c45bf16fe0983d80e3cfe750d6835843d265a9a6c46bd2e609fcddde6fb8d2a";

    @Test
    void everyNameParsesWhateverItsCaseAndTheDefaultIsKilted() {
        assertEquals(Ros2Distro.HUMBLE, Ros2Distro.parse("humble"), "humble");
        assertEquals(Ros2Distro.JAZZY, Ros2Distro.parse("Jazzy"), "Jazzy");
        assertEquals(Ros2Distro.KILTED, Ros2Distro.parse("kilted"), "kilted");
        assertEquals(Ros2Distro.ROLLING, Ros2Distro.parse("ROLLING"), "ROLLING");
        assertEquals(Ros2Distro.KILTED, Ros2Distro.newest(), "newest released distribution");
        assertEquals("kilted", Ros2Distro.newest().cliName(), "name as ROS writes it");
    }

    @Test
    void anUnknownNameIsRefusedNamingItAndTheAcceptedOnes() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Ros2Distro.parse("iron"));
        assertEquals("unknown ROS 2 distribution 'iron' (expected one of humble, jazzy, kilted, rolling)",
                e.getMessage(), "message");
    }

    @Test
    void humbleTopicKeysCarryTypeHashNotSupported() {
        assertEquals("0/cmd_vel/" + TWIST + "/TypeHashNotSupported",
                Ros2Names.topicKey(0, "/cmd_vel", TWIST, Ros2Distro.HUMBLE.typeHash(Ros2Types.TWIST)), "humble key");
    }

    @Test
    void jazzyKiltedAndRollingTopicKeysCarryTheRihs01Hash() {
        for (Ros2Distro d : new Ros2Distro[] {Ros2Distro.JAZZY, Ros2Distro.KILTED, Ros2Distro.ROLLING}) {
            assertEquals("0/robot1/cmd_vel/" + TWIST + "/" + TWIST_HASH,
                    Ros2Names.topicKey(0, "/robot1/cmd_vel", TWIST, d.typeHash(Ros2Types.TWIST)), d + " key");
        }
    }
}
