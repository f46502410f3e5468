package io.rtaware.foxglove;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.ByteBufUtil;
import io.netty.buffer.Unpooled;
import io.rtaware.record.TapChannel;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The protocol's messages on exact bytes, as the Foxglove WebSocket protocol v1 spells them. */
class FoxgloveProtocolTest {

    private final FoxgloveProtocol protocol = new FoxgloveProtocol();

    @Test
    void messageDataHeaderIsOpcodeOneThenSubscriptionIdAndTimestampLittleEndian() {
        ByteBuf out = Unpooled.buffer();
        FoxgloveProtocol.messageDataHeader(out, 0x01020304, 0x1122334455667788L);
        assertArrayEquals(new byte[] {0x01, 0x04, 0x03, 0x02, 0x01,
            (byte) 0x88, 0x77, 0x66, 0x55, 0x44, 0x33, 0x22, 0x11}, ByteBufUtil.getBytes(out),
                "opcode 0x01, uint32 subscription id, uint64 timestamp, both little-endian");
        assertEquals(FoxgloveProtocol.MESSAGE_DATA_HEADER_BYTES, out.readableBytes(), "13 bytes before the payload");
    }

    @Test
    void subscriptionIdsAboveIntMaxAreWrittenAsUint32() {
        ByteBuf out = Unpooled.buffer();
        FoxgloveProtocol.messageDataHeader(out, (int) 0xFFFF_FFFEL, 1);
        assertArrayEquals(new byte[] {0x01, (byte) 0xFE, (byte) 0xFF, (byte) 0xFF, (byte) 0xFF, 1, 0, 0, 0, 0, 0, 0, 0},
                ByteBufUtil.getBytes(out), "subscription id 4294967294");
    }

    @Test
    void serverInfoDeclaresTheTimeCapabilityAndCarriesTheMetadata() {
        assertEquals("{\"op\":\"serverInfo\",\"name\":\"rtaware run\",\"capabilities\":[\"time\"],\"supportedEncodings\":[],"
                        + "\"metadata\":{\"ROS_DISTRO\":\"jazzy\"},\"sessionId\":\"1700000000000\"}",
                protocol.serverInfo("rtaware run", "1700000000000", Map.of("ROS_DISTRO", "jazzy")));
    }

    @Test
    void aTimeFrameIsItsOpcodeThenTheTimeLittleEndian() {
        ByteBuf out = Unpooled.buffer();
        FoxgloveProtocol.time(out, 0x0102030405060708L);
        assertArrayEquals(new byte[] {0x02, 8, 7, 6, 5, 4, 3, 2, 1}, ByteBufUtil.getBytes(out));
    }

    @Test
    void advertiseGivesEachChannelItsCdrEncodingAndRos2msgSchema() {
        String json = protocol.advertise(List.of(
                new TapChannel(3, "/scan", "sensor_msgs/msg/LaserScan", "float32 angle_min\n", false),
                new TapChannel(4, "/tf_static", "tf2_msgs/msg/TFMessage", "x", true)));
        assertEquals("{\"op\":\"advertise\",\"channels\":["
                + "{\"id\":3,\"topic\":\"/scan\",\"encoding\":\"cdr\",\"schemaName\":\"sensor_msgs/msg/LaserScan\","
                + "\"schema\":\"float32 angle_min\\n\",\"schemaEncoding\":\"ros2msg\"},"
                + "{\"id\":4,\"topic\":\"/tf_static\",\"encoding\":\"cdr\",\"schemaName\":\"tf2_msgs/msg/TFMessage\","
                + "\"schema\":\"x\",\"schemaEncoding\":\"ros2msg\"}]}", json);
    }

    @Test
    void anEmptyAdvertiseIsStillAnAdvertise() {
        assertEquals("{\"op\":\"advertise\",\"channels\":[]}", protocol.advertise(List.of()));
    }

    @Test
    void statusHasLevelAndMessage() {
        assertEquals("{\"op\":\"status\",\"level\":1,\"message\":\"no channel 9\"}",
                protocol.status(FoxgloveProtocol.STATUS_WARNING, "no channel 9"));
    }

    @Test
    void readsSubscribeWithEverySubscription() {
        FoxgloveProtocol.Request r = protocol.read(
                "{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":0,\"channelId\":3},{\"id\":4294967295,\"channelId\":5}]}");
        assertEquals(new FoxgloveProtocol.Subscribe(List.of(new FoxgloveProtocol.Subscription(0, 3),
                new FoxgloveProtocol.Subscription(4294967295L, 5))), r);
    }

    @Test
    void readsUnsubscribe() {
        assertEquals(new FoxgloveProtocol.Unsubscribe(List.of(0L, 1L)),
                protocol.read("{\"op\":\"unsubscribe\",\"subscriptionIds\":[0,1]}"));
    }

    @Test
    void otherOpsAreUnsupportedNotErrors() {
        assertEquals(new FoxgloveProtocol.Unsupported("advertise"), protocol.read(
                "{\"op\":\"advertise\",\"channels\":[{\"id\":1,\"topic\":\"/x\",\"encoding\":\"json\",\"schemaName\":\"X\"}]}"));
        assertEquals(new FoxgloveProtocol.Unsupported("getParameters"),
                protocol.read("{\"op\":\"getParameters\",\"parameterNames\":[]}"));
    }

    @ParameterizedTest
    @ValueSource(strings = {
        "not json",
        "[]",
        "{\"op\":3}",
        "{\"subscriptions\":[]}",
        "{\"op\":\"subscribe\"}",
        "{\"op\":\"subscribe\",\"subscriptions\":{}}",
        "{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":-1,\"channelId\":3}]}",
        "{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":4294967296,\"channelId\":3}]}",
        "{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":1.5,\"channelId\":3}]}",
        "{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":\"1\",\"channelId\":3}]}",
        "{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":1}]}",
        "{\"op\":\"subscribe\",\"subscriptions\":[7]}",
        "{\"op\":\"unsubscribe\",\"subscriptionIds\":[\"a\"]}",
        "{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":1,\"channelId\":100000000000000000000000}]}"
    })
    void aMalformedClientMessageIsOneLineNotACrash(String text) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> protocol.read(text), text);
        assertEquals(1, e.getMessage().lines().count(), "one line: " + e.getMessage());
        assertTrue(!e.getMessage().isBlank(), "says what is wrong");
    }
}
