package io.rtaware.ros2.graph;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.testing.Requires;
import io.rtaware.core.testing.Waits;
import io.rtaware.ros2msg.Ros2Types;
import io.rtaware.zenoh.NativeZenohLayer;
import io.rtaware.zenoh.SampleBuffer;
import io.rtaware.zenoh.ZenohConfig;
import io.rtaware.zenoh.ZenohMailbox;
import java.net.ServerSocket;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The key expressions and liveliness tokens a node declares, checked on the wire against strings
 * written out by hand from the rmw_zenoh conventions (design document and rmw_zenoh_cpp's
 * liveliness_utils, 2025): the topic key is {@code <domain>/<fully qualified topic without its
 * leading slash>/<DDS type>/<hash>}, so a relative name in namespace {@code /robot1} lands under
 * {@code robot1/} and an absolute name ignores the namespace; in tokens every {@code /} of a
 * name is {@code %}, the root namespace and the default enclave are a single {@code %}, and node
 * and entity ids count from 0 within a context.
 */
@Timeout(60)
@Requires(NativeZenohLayer.class)
class Ros2NodeKeysTest {

    private static final String SCAN_TYPE = "sensor_msgs::msg::dds_::LaserScan_/" + Ros2Types.LASER_SCAN.typeHash();
    private static final String SENSOR_QOS = "2::,5:,:,:,,";

    private Ros2Context robot;
    private Ros2Context watcher;
    private String endpoint;
    /** The gid in the attachment of the last sample {@link #arrivesOn} received. */
    private byte[] lastGid;

    @BeforeEach
    void open() throws Exception {
        try (ServerSocket s = new ServerSocket(0)) {
            endpoint = "tcp/127.0.0.1:" + s.getLocalPort();
        }
        robot = Ros2Context.open(ZenohConfig.loopbackPeer().withListen(List.of(endpoint)), 7);
        watcher = Ros2Context.open(ZenohConfig.loopbackPeer().withConnect(List.of(endpoint)), 7);
    }

    @AfterEach
    void close() throws Exception {
        if (watcher != null) {
            watcher.close();
        }
        if (robot != null) {
            robot.close();
        }
    }

    /** Publishes until the watcher's raw subscription on {@code key} gets a sample (subscriptions propagate asynchronously). */
    private void arrivesOn(Ros2Publisher publisher, String key) throws Exception {
        ZenohMailbox mailbox = watcher.session().newMailbox(8);
        mailbox.subscribe(key, 3);
        SampleBuffer sample = new SampleBuffer(1024, 64);
        byte[] message = {0, 1, 0, 0, 42};
        Waits.until(() -> {
            publisher.publish(message, message.length, 1);
            return mailbox.take(TimeUnit.MILLISECONDS.toNanos(50), sample) == ZenohMailbox.Take.SAMPLE;
        }, Duration.ofSeconds(10), "a sample on " + key);
        assertEquals(3, sample.channel());
        assertTrue(SampleAttachment.valid(sample.attachment(), sample.attachmentLength()), "rmw_zenoh attachment");
        lastGid = new byte[SampleAttachment.GID_BYTES];
        sample.attachment().get(SampleAttachment.GID_OFFSET, lastGid);
        mailbox.close();
    }

    @Test
    void relativeNamesLandUnderTheNamespaceAndAbsoluteNamesDoNot() throws Exception {
        Ros2Node node = robot.createNode("/robot1", "talker");
        Ros2Publisher relative = node.createPublisher("scan", Ros2Types.LASER_SCAN, QosProfile.sensorData(), 1024);
        Ros2Publisher absolute = node.createPublisher("/scan", Ros2Types.LASER_SCAN, QosProfile.sensorData(), 1024);
        arrivesOn(relative, "7/robot1/scan/" + SCAN_TYPE);
        arrivesOn(absolute, "7/scan/" + SCAN_TYPE);

        String zid = robot.session().zid();
        List<String> tokens = watcher.session().livelinessKeys("@ros2_lv/7/" + zid + "/**", 2000);
        assertTrue(tokens.contains("@ros2_lv/7/" + zid + "/0/0/NN/%/%robot1/talker"), "node token in " + tokens);
        assertTrue(tokens.contains("@ros2_lv/7/" + zid + "/0/1/MP/%/%robot1/talker/%robot1%scan/" + SCAN_TYPE + "/"
                + SENSOR_QOS), "relative publisher's token in " + tokens);
        assertTrue(tokens.contains("@ros2_lv/7/" + zid + "/0/2/MP/%/%robot1/talker/%scan/" + SCAN_TYPE + "/"
                + SENSOR_QOS), "absolute publisher's token in " + tokens);
        assertEquals(3, tokens.size(), "one token per entity: " + tokens);
    }

    @Test
    void theRootNamespaceIsASinglePercentAndIdsCountOnAcrossNodes() throws Exception {
        robot.createNode("/robot1", "first");
        Ros2Node node = robot.createNode("/", "second");
        Ros2Publisher cmdVel = node.createPublisher("cmd_vel", Ros2Types.TWIST, QosProfile.defaults(), 1024);
        String twist = "geometry_msgs::msg::dds_::Twist_/" + Ros2Types.TWIST.typeHash();
        arrivesOn(cmdVel, "7/cmd_vel/" + twist);

        String zid = robot.session().zid();
        List<String> tokens = watcher.session().livelinessKeys("@ros2_lv/7/" + zid + "/**", 2000);
        assertTrue(tokens.contains("@ros2_lv/7/" + zid + "/1/1/NN/%/%/second"), "root-namespace node in " + tokens);
        assertTrue(tokens.contains("@ros2_lv/7/" + zid + "/1/2/MP/%/%/second/%cmd_vel/" + twist + "/::,10:,:,:,,"),
                "default-QoS publisher in " + tokens);
    }

    @Test
    void aHumbleContextWritesTypeHashNotSupportedAndSendsTheGidOfItsToken() throws Exception {
        try (Ros2Context humble = Ros2Context.open(ZenohConfig.loopbackPeer().withConnect(
                List.of(endpoint)), 7,
                Ros2Distro.HUMBLE)) {
            Ros2Node node = humble.createNode("/", "old");
            Ros2Publisher cmdVel = node.createPublisher("cmd_vel", Ros2Types.TWIST, QosProfile.defaults(), 1024);
            String twist = "geometry_msgs::msg::dds_::Twist_/TypeHashNotSupported";
            arrivesOn(cmdVel, "7/cmd_vel/" + twist);

            String zid = humble.session().zid();
            String token = "@ros2_lv/7/" + zid + "/0/1/MP/%/%/old/%cmd_vel/" + twist + "/::,10:,:,:,,";
            List<String> tokens = watcher.session().livelinessKeys("@ros2_lv/7/" + zid + "/**", 2000);
            assertTrue(tokens.contains(token), "humble publisher's token in " + tokens);
            assertEquals(token, cmdVel.tokenKey(), "the token the publisher holds");
            assertArrayEquals(Ros2Publisher.gid(token), lastGid, "gid in the attachment is XXH3-128 of the token");
        }
    }
}
