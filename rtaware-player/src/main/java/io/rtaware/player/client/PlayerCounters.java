package io.rtaware.player.client;

/**
 * Running counters of one or more successive Player connections (a reconnecting task passes
 * the same instance to every client). Written by one thread (the connection's owner); read
 * from any thread through {@link #snapshot()}, which sees each counter's latest value (the
 * counters are volatile, so a snapshot may mix values of neighbouring instants).
 */
public final class PlayerCounters {

    volatile long messagesReceived;
    volatile long bytesReceived;
    volatile long messagesSent;
    volatile long bytesSent;
    volatile long protocolErrors;
    volatile long skippedMessages;
    volatile long odometryMessages;
    volatile long scanMessages;
    volatile long synchs;
    volatile long commandsSent;
    volatile long connects;
    volatile long connectionLosses;

    /** Counters at zero. */
    public PlayerCounters() {
    }

    /** Counts one lost or failed connection; called by the connection's owner. */
    public void connectionLost() {
        connectionLosses++;
    }

    /** Counts one protocol error found outside a client (e.g. by a connection's owner). */
    public void protocolError() {
        protocolErrors++;
    }

    /** @return the current values */
    public PlayerStats snapshot() {
        return new PlayerStats(messagesReceived, bytesReceived, messagesSent, bytesSent, protocolErrors,
                skippedMessages, odometryMessages, scanMessages, synchs, commandsSent, connects, connectionLosses);
    }
}
