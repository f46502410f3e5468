package io.rtaware.player.client;

/**
 * A snapshot of a Player connection's counters, for reports. Immutable and thread-safe.
 *
 * @param messagesReceived messages received
 * @param bytesReceived bytes received, banner included
 * @param messagesSent messages sent
 * @param bytesSent bytes sent
 * @param protocolErrors malformed messages and broken streams
 * @param skippedMessages messages of interfaces or subtypes this client does not use
 * @param odometryMessages position2d states received
 * @param scanMessages laser scans and ranger ranges received
 * @param synchs SYNCH messages received (PULL rounds)
 * @param commandsSent velocity commands sent
 * @param connects successful connections
 * @param connectionLosses connections lost or failed
 * @param rejectedOdometry position2d states that could not be true and were dropped
 * @param rejectedScans laser scans and ranger ranges that could not be true and were dropped
 */
public record PlayerStats(long messagesReceived, long bytesReceived, long messagesSent, long bytesSent,
                          long protocolErrors, long skippedMessages, long odometryMessages, long scanMessages,
                          long synchs, long commandsSent, long connects, long connectionLosses,
                          long rejectedOdometry, long rejectedScans) {
}
