package io.rtaware.player.protocol;

/**
 * Player message type codes ({@code PLAYER_MSGTYPE_*}). Constants only; thread-safe.
 */
public final class MessageType {

    /** Asynchronous data from a subscribed device (server to client). */
    public static final int DATA = 1;
    /** Asynchronous command, never answered (client to server). */
    public static final int CMD = 2;
    /** Request, answered by {@link #RESP_ACK} or {@link #RESP_NACK}. */
    public static final int REQ = 3;
    /** Positive reply; same address and subtype as the request. */
    public static final int RESP_ACK = 4;
    /** End of one PULL round. */
    public static final int SYNCH = 5;
    /** Negative reply; same address and subtype as the request. */
    public static final int RESP_NACK = 6;

    private MessageType() {
    }

    /**
     * @param type a type code
     * @return its name, e.g. {@code RESP_ACK}, or {@code type<code>} if unknown
     */
    public static String name(int type) {
        return switch (type) {
            case DATA -> "DATA";
            case CMD -> "CMD";
            case REQ -> "REQ";
            case RESP_ACK -> "RESP_ACK";
            case SYNCH -> "SYNCH";
            case RESP_NACK -> "RESP_NACK";
            default -> "type" + type;
        };
    }
}
