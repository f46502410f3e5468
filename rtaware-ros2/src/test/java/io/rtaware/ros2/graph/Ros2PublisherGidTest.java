package io.rtaware.ros2.graph;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import java.util.HexFormat;
import org.junit.jupiter.api.Test;

/**
 * The publisher gid as rmw_zenoh derives it: rmw_zenoh_cpp's {@code liveliness::Entity}
 * constructor ({@code rmw_zenoh_cpp/src/detail/liveliness_utils.cpp}, ros2/rmw_zenoh commit
 * 97aed4819677b9825b20bb44a01707f42843e06a "Add the GID hash to get_entities_info_by_topic
 * (#298)" and unchanged at 3411fdec149fe0c932f24d4d79ef908eb81d7482) hashes the entity's whole
 * liveliness key expression with {@code simplified_XXH3_128bits} and copies {@code low64}, then
 * {@code high64}, into the 16-byte gid (little-endian hosts). The expected values were computed
 * by compiling rmw_zenoh's own {@code simplified_xxhash3.cpp} (commit bfc065f8c80c) with g++ and
 * printing the 16 bytes of that memcpy, and agree with Python {@code xxhash} 3.x's
 * {@code xxh3_128(key).digest()} read backwards (the canonical digest is big endian,
 * high64 first). The inputs cover XXH3's short (1-3 bytes), 17-128 and 129-240 byte paths.
 */
class Ros2PublisherGidTest {

    private static final String ZID = "1f2e3d4c5b6a79881f2e3d4c5b6a7988";

    private static String hex(byte[] gid) {
        return HexFormat.of().formatHex(gid);
    }

    @Test
    void aShortKeyHashesAsXxh3OfItsBytesLowHalfFirst() {
        assertEquals("50392f89945faf7885613a73b65ab006", hex(Ros2Publisher.gid("abc")),
                "XXH3-128 of 'abc', low64 then high64, little endian");
    }

    @Test
    void aJazzyPublisherTokenGivesTheGidRmwZenohComputesForIt() {
        String token = "@ros2_lv/0/" + ZID + "/0/1/MP/%/%/rtaware/%cmd_vel/geometry_msgs::msg::dds_::Twist_/"
                + "RIHS01_9c45bf16fe0983d80e3cfe750d6835843d265a9a6c46bd2e609fcddde6fb8d2a/::,10:,:,:,,";
        assertEquals(189, token.length(), "the 129-240 byte path of XXH3");
        assertEquals("b9cded1cd354de9cd84bf2b88ef52ccb", hex(Ros2Publisher.gid(token)), "gid of " + token);
    }

    @Test
    void aHumblePublisherTokenGivesTheGidRmwZenohComputesForIt() {
        String token = "@ros2_lv/0/" + ZID + "/0/1/MP/%/%/rtaware/%cmd_vel/geometry_msgs::msg::dds_::Twist_/"
                + "TypeHashNotSupported/::,10:,:,:,,";
        assertEquals("0b75a9d73f8c6d076b6ee08ea540f71e", hex(Ros2Publisher.gid(token)), "gid of " + token);
    }

    @Test
    void aNodeTokenOfSeventeenToOneHundredTwentyEightBytesGivesRmwZenohsGid() {
        String token = "@ros2_lv/0/" + ZID + "/0/0/NN/%/%/rtaware";
        assertEquals(62, token.length(), "the 17-128 byte path of XXH3");
        assertEquals("ed96e8f8031a3ddee3893fe2a65e4028", hex(Ros2Publisher.gid(token)), "gid of " + token);
    }

    @Test
    void publishersThatDifferOnlyInEntityIdHaveDifferentGids() {
        String first = "@ros2_lv/0/" + ZID + "/0/1/MP/%/%/rtaware/%a/std_msgs::msg::dds_::Empty_/TypeHashNotSupported/::,10:,:,:,,";
        String second = first.replace("/0/1/MP/", "/0/2/MP/");
        assertNotEquals(hex(Ros2Publisher.gid(first)), hex(Ros2Publisher.gid(second)), "entity ids 1 and 2");
    }
}
