package io.rtaware.foxglove;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import io.netty.buffer.ByteBuf;
import io.rtaware.record.TapChannel;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * The messages of the Foxglove WebSocket protocol that rtaware's server sends and reads, as
 * foxglove_bridge speaks it under either subprotocol, {@value #SUBPROTOCOL_SDK} (foxglove_bridge
 * 3.x and the Foxglove SDK, preferred) or {@value #SUBPROTOCOL} (older clients): JSON text
 * messages with an {@code op} (server: {@code serverInfo}, {@code advertise}, {@code status};
 * client: {@code subscribe}, {@code unsubscribe}), the binary Message Data frame (opcode
 * {@value #MESSAGE_DATA}, uint32 subscription id, uint64 log time in ns, little-endian, then the
 * payload) and the binary Time frame (opcode {@value #TIME}, uint64 time in ns, little-endian)
 * of the {@value #CAPABILITY_TIME} capability. Stateless; thread-safe.
 */
public final class FoxgloveProtocol {

    /** The WebSocket subprotocol of older clients (Foxglove's ws-protocol packages, Lichtblick). */
    public static final String SUBPROTOCOL = "foxglove.websocket.v1";
    /** The WebSocket subprotocol of foxglove_bridge 3.x and the Foxglove SDK; selected when offered. */
    public static final String SUBPROTOCOL_SDK = "foxglove.sdk.v1";
    /** The capability of a server that broadcasts its time, so the client's timeline follows it. */
    public static final String CAPABILITY_TIME = "time";
    /** Opcode of a binary Time frame from the server. */
    public static final byte TIME = 0x02;
    /** Bytes of a Time frame: opcode, timestamp. */
    public static final int TIME_BYTES = 1 + 8;
    /** Opcode of a binary Message Data frame from the server. */
    public static final byte MESSAGE_DATA = 0x01;
    /** Bytes before the payload in a Message Data frame: opcode, subscription id, timestamp. */
    public static final int MESSAGE_DATA_HEADER_BYTES = 1 + 4 + 8;
    /** Status level: information. */
    public static final int STATUS_INFO = 0;
    /** Status level: warning. */
    public static final int STATUS_WARNING = 1;
    /** Status level: error. */
    public static final int STATUS_ERROR = 2;
    /** Largest subscription id (a uint32). */
    static final long MAX_SUBSCRIPTION_ID = 0xFFFF_FFFFL;

    private final ObjectMapper mapper = new ObjectMapper();

    /**
     * The Server Info message, sent first to every client. Of the optional capabilities rtaware's
     * server has {@value #CAPABILITY_TIME} only (no client publishing, parameters or services).
     *
     * @param name the server's name
     * @param sessionId what tells a reconnection from a new server (e.g. the start time)
     * @param metadata free key/value pairs (e.g. {@code ROS_DISTRO})
     * @return the JSON text
     */
    public String serverInfo(String name, String sessionId, Map<String, String> metadata) {
        ObjectNode root = mapper.createObjectNode();
        root.put("op", "serverInfo");
        root.put("name", name);
        root.putArray("capabilities").add(CAPABILITY_TIME);
        root.putArray("supportedEncodings");
        ObjectNode meta = root.putObject("metadata");
        metadata.forEach(meta::put);
        root.put("sessionId", sessionId);
        return text(root);
    }

    /**
     * The Advertise message of channels: each with its id, topic, encoding {@code cdr}, schema
     * name (the ROS 2 type), schema (its {@code ros2msg} text) and schema encoding
     * {@code ros2msg}.
     *
     * @param channels the channels (may be empty: a new client always gets one Advertise)
     * @return the JSON text
     */
    public String advertise(List<TapChannel> channels) {
        ObjectNode root = mapper.createObjectNode();
        root.put("op", "advertise");
        ArrayNode array = root.putArray("channels");
        for (TapChannel c : channels) {
            ObjectNode channel = array.addObject();
            channel.put("id", c.id());
            channel.put("topic", c.topic());
            channel.put("encoding", TapChannel.MESSAGE_ENCODING);
            channel.put("schemaName", c.schemaName());
            channel.put("schema", c.schema());
            channel.put("schemaEncoding", TapChannel.SCHEMA_ENCODING);
        }
        return text(root);
    }

    /**
     * A Status message.
     *
     * @param level {@link #STATUS_INFO}, {@link #STATUS_WARNING} or {@link #STATUS_ERROR}
     * @param message what to tell the user
     * @return the JSON text
     */
    public String status(int level, String message) {
        ObjectNode root = mapper.createObjectNode();
        root.put("op", "status");
        root.put("level", level);
        root.put("message", message);
        return text(root);
    }

    /**
     * Writes the header of a Message Data frame; the payload follows it.
     *
     * @param out the frame's buffer
     * @param subscriptionId the client's subscription id (a uint32, kept in an int's bits)
     * @param timestampNs the message's log time, ns
     */
    public static void messageDataHeader(ByteBuf out, int subscriptionId, long timestampNs) {
        out.writeByte(MESSAGE_DATA);
        out.writeIntLE(subscriptionId);
        out.writeLongLE(timestampNs);
    }

    /**
     * Writes a Time frame.
     *
     * @param out the frame's buffer, with {@value #TIME_BYTES} bytes of room
     * @param timestampNs the server's time, ns (the run's log time: Unix epoch plus world time)
     */
    public static void time(ByteBuf out, long timestampNs) {
        out.writeByte(TIME);
        out.writeLongLE(timestampNs);
    }

    /** A client's request, as read by {@link #read}. */
    public sealed interface Request permits Subscribe, Unsubscribe, Unsupported {
    }

    /**
     * One subscription of a Subscribe message.
     *
     * @param id the client's subscription id (0..2^32-1)
     * @param channelId the advertised channel's id
     */
    public record Subscription(long id, long channelId) {
    }

    /**
     * {@code {"op":"subscribe","subscriptions":[{"id":0,"channelId":3}]}}.
     *
     * @param subscriptions what the client asks for
     */
    public record Subscribe(List<Subscription> subscriptions) implements Request {
    }

    /**
     * {@code {"op":"unsubscribe","subscriptionIds":[0]}}.
     *
     * @param subscriptionIds the subscriptions to end
     */
    public record Unsubscribe(List<Long> subscriptionIds) implements Request {
    }

    /**
     * Any other op (client publishing, parameters, services, ...): the server has none of those
     * capabilities.
     *
     * @param op the message's op
     */
    public record Unsupported(String op) implements Request {
    }

    /**
     * Reads a client's text message.
     *
     * @param text the JSON text
     * @return the request
     * @throws IllegalArgumentException with one line saying what is wrong, if it is not a valid
     *     message of the protocol
     */
    public Request read(String text) {
        JsonNode root;
        try {
            root = mapper.readTree(text);
        } catch (JsonProcessingException e) {
            throw new IllegalArgumentException("not JSON: " + e.getOriginalMessage());
        }
        if (root == null || !root.isObject() || !root.path("op").isTextual()) {
            throw new IllegalArgumentException("not a JSON object with a string 'op'");
        }
        String op = root.get("op").asText();
        if (op.equals("subscribe")) {
            List<Subscription> list = new ArrayList<>();
            for (JsonNode s : array(root, "subscriptions")) {
                list.add(new Subscription(id(s.get("id"), "subscriptions[].id"),
                        id(s.get("channelId"), "subscriptions[].channelId")));
            }
            return new Subscribe(List.copyOf(list));
        }
        if (op.equals("unsubscribe")) {
            List<Long> ids = new ArrayList<>();
            for (JsonNode id : array(root, "subscriptionIds")) {
                ids.add(id(id, "subscriptionIds[]"));
            }
            return new Unsubscribe(List.copyOf(ids));
        }
        return new Unsupported(op);
    }

    private static JsonNode array(JsonNode root, String field) {
        JsonNode array = root.get(field);
        if (array == null || !array.isArray()) {
            throw new IllegalArgumentException("'" + root.get("op").asText() + "' without an array '" + field + "'");
        }
        return array;
    }

    private static long id(JsonNode node, String what) {
        if (node == null || !node.canConvertToLong() || !node.isIntegralNumber() || node.asLong() < 0
                || node.asLong() > MAX_SUBSCRIPTION_ID) {
            throw new IllegalArgumentException(what + " must be an integer 0..4294967295, got " + node);
        }
        return node.asLong();
    }

    private String text(ObjectNode root) {
        try {
            return mapper.writeValueAsString(root);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("a tree of strings and numbers always serializes", e);
        }
    }
}
