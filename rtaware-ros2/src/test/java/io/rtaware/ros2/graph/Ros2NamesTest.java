package io.rtaware.ros2.graph;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import io.rtaware.ros2msg.Ros2Types;
import org.junit.jupiter.api.Test;

class Ros2NamesTest {

    @Test
    void topicKeyFollowsTheRmwZenohDesignExample() {
        assertEquals("0/cmd_vel/geometry_msgs::msg::dds_::Twist_/"
                        + "RIHS01_9c45bf16fe0983d80e3cfe750d6835843d265a9a6c46bd2e609fcddde6fb8d2a",
                Ros2Names.topicKey(0, "/cmd_vel", Ros2Types.TWIST.ddsTypeName(), Ros2Types.TWIST.typeHash()));
    }

    @Test
    void namespacesStayPathSegments() {
        String full = Ros2Names.resolveTopic(Ros2Names.namespace("robot1/"), "cmd_vel");
        assertEquals("/robot1/cmd_vel", full);
        assertEquals("3/robot1/cmd_vel/T/H", Ros2Names.topicKey(3, full, "T", "H"));
        assertEquals("/scan", Ros2Names.resolveTopic("/robot1", "/scan"), "absolute names ignore the namespace");
        assertEquals("/scan", Ros2Names.resolveTopic("/", "scan"));
    }

    /**
     * The bridge's keys and announcements as zenoh-plugin-ros2dds 1.10.2 writes and parses them
     * ({@code ros2_utils.rs} {@code ros2_name_to_key_expr}, {@code liveliness_mgt.rs}
     * {@code ke_liveliness_pub}/{@code ke_liveliness_sub}, {@code escape_slashes}).
     */
    @Test
    void bridgeKeysDropTheLeadingSlashAndAnnouncementsEscapeSlashesWithSectionSigns() {
        assertEquals("scan", Ros2Names.bridgeKey("/scan"));
        assertEquals("robot1/scan", Ros2Names.bridgeKey("/robot1/scan"));
        assertEquals("@/5e1f/@ros2_lv/MP/robot1§scan/sensor_msgs§msg§LaserScan/:0:0:0,5",
                Ros2Names.bridgeAnnouncement("5e1f", "MP", "/robot1/scan", "sensor_msgs/msg/LaserScan",
                        QosProfile.sensorData(), null));
        assertEquals("@/5e1f/@ros2_lv/MS/cmd_vel/geometry_msgs§msg§Twist/:1:0:0,10:typehash=" + Ros2Types.TWIST.typeHash() + ";",
                Ros2Names.bridgeAnnouncement("5e1f", "MS", "/cmd_vel", Ros2Types.TWIST.name(), QosProfile.defaults(),
                        Ros2Types.TWIST.typeHash()));
    }

    @Test
    void namesInTokensReplaceSlashesAndMarkEmptyNames() {
        assertEquals("%robot1%cmd_vel", Ros2Names.mangle("/robot1/cmd_vel"));
        assertEquals("%", Ros2Names.mangle(""));
        assertEquals("%", Ros2Names.mangle("/"));
    }

    @Test
    void ddsTypeNamesReadAsRos2TypeNamesAndOtherNamesStayAsTheyAre() {
        assertEquals("geometry_msgs/msg/Twist", Ros2Names.rosTypeName("geometry_msgs::msg::dds_::Twist_"));
        assertEquals("sensor_msgs/msg/LaserScan", Ros2Names.rosTypeName(Ros2Types.LASER_SCAN.ddsTypeName()));
        assertEquals("ShapeType", Ros2Names.rosTypeName("ShapeType"), "a plain DDS application's type");
        assertEquals("a::dds_::B", Ros2Names.rosTypeName("a::dds_::B"), "no trailing underscore: not ROS 2's form");
    }

    @Test
    void invalidNamesAreRejectedWithTheirText() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> Ros2Names.resolveTopic("/", "bad topic"));
        assertEquals("invalid ROS 2 topic name 'bad topic'", e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> Ros2Names.namespace("/9robot"));
        assertThrows(IllegalArgumentException.class, () -> Ros2Names.nodeName("a/b"));
        assertThrows(IllegalArgumentException.class, () -> Ros2Names.resolveTopic("/", "scan/"));
    }

    @Test
    void hashesMatchThePrefixesFromTheJazzyDefinitions() {
        assertEquals("RIHS01_64c19139", Ros2Types.LASER_SCAN.typeHash().substring(0, 15));
        assertEquals("RIHS01_3cc97dc7", Ros2Types.ODOMETRY.typeHash().substring(0, 15));
        assertEquals("sensor_msgs::msg::dds_::LaserScan_", Ros2Types.LASER_SCAN.ddsTypeName());
    }
}
