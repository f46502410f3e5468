package io.rtaware.foxglove;

/**
 * What the Foxglove server did: the {@code foxglove} section of a run's report.
 *
 * @param address where it listened, {@code HOST:PORT}
 * @param maxClients clients served at once; more were refused after their handshake
 * @param sendBufferBytes bytes each client may have waiting to be sent; a message that does not
 *     fit is dropped for that client
 * @param clientsAccepted clients that connected
 * @param clientsRefused clients refused because {@code maxClients} were connected (or the server
 *     was closing)
 * @param messagesSent messages sent (one per subscribed client)
 * @param bytesSent bytes of those messages (Message Data frames, WebSocket framing not included)
 * @param messagesDropped messages not sent to a client because its send buffer was full (a slow
 *     client); the tasks never wait for a client
 * @param statusesDropped status messages (warnings and errors about a client's requests) not sent
 *     because that client's send buffer was full
 * @param clientsClosedSlow clients closed because their send buffer had no room for their Server
 *     Info or an advertisement (they would have missed channels for good)
 * @param connectionsClosedInHandshake connections closed before their WebSocket handshake was done:
 *     not done within {@link FoxgloveServer#HANDSHAKE_TIMEOUT_MS} ms of connecting, or the oldest
 *     when {@link FoxgloveServer#MAX_PENDING_HANDSHAKES} were pending
 */
public record FoxgloveStats(String address, int maxClients, long sendBufferBytes, long clientsAccepted,
                            long clientsRefused, long messagesSent, long bytesSent, long messagesDropped,
                            long statusesDropped, long clientsClosedSlow, long connectionsClosedInHandshake) {
}
