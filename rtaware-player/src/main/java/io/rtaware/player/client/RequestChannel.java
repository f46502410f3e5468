package io.rtaware.player.client;

import io.rtaware.player.protocol.DeviceAddress;
import io.rtaware.player.protocol.MessageType;
import io.rtaware.player.protocol.PlayerHeader;
import io.rtaware.player.xdr.XdrReader;
import java.io.IOException;
import java.util.concurrent.TimeUnit;

/**
 * Request and reply over a {@link PlayerConnection}: sends a request and waits, at most the
 * request timeout of wall time, for the reply from the same interface, index and subtype; a
 * RESP_NACK becomes {@link PlayerNackException}. Every other message read while waiting goes to
 * {@link SubscribedData}, so no data is lost to a request. Not thread-safe.
 */
final class RequestChannel {

    private final PlayerConnection connection;
    private final SubscribedData data;
    private final int requestTimeoutMs;

    RequestChannel(PlayerConnection connection, SubscribedData data, int requestTimeoutMs) {
        this.connection = connection;
        this.data = data;
        this.requestTimeoutMs = requestTimeoutMs;
    }

    /**
     * Sends the message begun at {@code headerAt} and waits for its reply.
     *
     * @param dev the device that answers
     * @param subtype the request's subtype
     * @param what the request in words, for errors
     * @return the reply's body
     * @throws PlayerTimeoutException if no reply came in time
     * @throws PlayerNackException if the server refused
     * @throws IOException if the connection fails
     */
    XdrReader request(DeviceAddress dev, int subtype, String what, int headerAt) throws IOException {
        connection.send(headerAt);
        return awaitReply(dev, subtype, what, connection.server() + " refused " + what + " (RESP_NACK from " + dev
                + ")");
    }

    /**
     * Waits for the reply to a request already sent.
     *
     * @param nackMessage the message of the exception thrown on RESP_NACK
     * @return the reply's body
     */
    XdrReader awaitReply(DeviceAddress dev, int subtype, String what, String nackMessage) throws IOException {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(requestTimeoutMs);
        while (true) {
            long leftNs = deadline - System.nanoTime();
            PlayerHeader h = leftNs <= 0 ? null : connection.readOne(leftNs);
            if (h == null) {
                throw new PlayerTimeoutException("no reply from " + dev + " to " + what + " within "
                        + requestTimeoutMs + " ms (Player does not answer requests to devices it does not have)");
            }
            boolean reply = h.type() == MessageType.RESP_ACK || h.type() == MessageType.RESP_NACK;
            if (reply && h.interf() == dev.interf() && h.index() == dev.index() && h.subtype() == subtype) {
                if (h.type() == MessageType.RESP_NACK) {
                    throw new PlayerNackException(nackMessage);
                }
                return connection.body();
            }
            data.dispatch(h, connection.body());
        }
    }
}
