package io.rtaware.player.client;

import io.rtaware.robot.validate.SampleLimits;
import io.rtaware.robot.validate.SampleValidator;

/**
 * Running counters of one or more successive Player connections (a reconnecting task passes
 * the same instance to every client). Written by one thread (the connection's owner); read
 * from any thread through {@link #snapshot()}, which sees each counter's latest value (the
 * counters are volatile, so a snapshot may mix values of neighbouring instants). It also holds
 * the {@link SampleValidator} of each data kind (position2d, laser, ranger), so rejected samples
 * are counted across reconnections; each new connection restarts their timestamp memory.
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

    private final SampleValidator odometryChecks;
    private final SampleValidator laserChecks;
    private final SampleValidator rangerChecks;

    /** Counters at zero, checking samples against {@link SampleLimits#defaults()}. */
    public PlayerCounters() {
        this(SampleLimits.defaults());
    }

    /** @param limits the bounds a sample must respect to be kept */
    public PlayerCounters(SampleLimits limits) {
        odometryChecks = new SampleValidator("position2d", limits);
        laserChecks = new SampleValidator("laser", limits);
        rangerChecks = new SampleValidator("ranger", limits);
    }

    /** @return the checks of position2d states; counts their rejections */
    public SampleValidator odometryChecks() {
        return odometryChecks;
    }

    /** @return the checks of laser scans */
    public SampleValidator laserChecks() {
        return laserChecks;
    }

    /** @return the checks of ranger ranges (as scans) */
    public SampleValidator rangerChecks() {
        return rangerChecks;
    }

    /** A new connection: timestamps of its samples may start again. */
    void newConnection() {
        odometryChecks.restart();
        laserChecks.restart();
        rangerChecks.restart();
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
                skippedMessages, odometryMessages, scanMessages, synchs, commandsSent, connects, connectionLosses,
                odometryChecks.rejected(), laserChecks.rejected() + rangerChecks.rejected());
    }
}
