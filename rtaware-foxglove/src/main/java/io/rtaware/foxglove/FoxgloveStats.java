package io.rtaware.foxglove;

/**
 * What the Foxglove server did: the {@code foxglove} section of a run's report.
 *
 * @param address where it listened, {@code HOST:PORT}
 * @param maxClients clients served at once; more were refused
 * @param sendBufferBytes bytes each client may have waiting to be sent; a message that does not
 *     fit is dropped for that client
 * @param clientsAccepted clients that connected
 * @param clientsRefused connections refused because {@code maxClients} were connected
 * @param messagesSent messages sent (one per subscribed client)
 * @param bytesSent bytes of those messages (Message Data frames, WebSocket framing not included)
 * @param messagesDropped messages not sent to a client because its send buffer was full (a slow
 *     client); the tasks never wait for a client
 */
public record FoxgloveStats(String address, int maxClients, long sendBufferBytes, long clientsAccepted,
                            long clientsRefused, long messagesSent, long bytesSent, long messagesDropped) {
}
