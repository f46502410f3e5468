package io.rtaware.player.client;

import io.rtaware.player.protocol.Interfaces;
import io.rtaware.player.protocol.LaserData;
import io.rtaware.player.protocol.MessageType;
import io.rtaware.player.protocol.PlayerCodec;
import io.rtaware.player.protocol.PlayerHeader;
import io.rtaware.player.protocol.RangerConfig;
import io.rtaware.player.protocol.RangerData;
import io.rtaware.player.protocol.Subtypes;
import io.rtaware.player.xdr.PlayerProtocolException;
import io.rtaware.player.xdr.XdrReader;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.Odometry;

/**
 * What a client keeps of the messages that are not replies: the newest position2d state, laser
 * scan and ranger ranges of the subscribed indices, and the SYNCH count. Each data message is
 * decoded into a scratch buffer and checked by the device's
 * {@link io.rtaware.robot.validate.SampleValidator} (in {@link PlayerCounters}); only a sample
 * that can be true replaces the newest one, a rejected one is counted and dropped. Messages of
 * other devices or subtypes are counted as skipped, a malformed data body as a protocol error.
 * Allocates nothing per message. Not thread-safe.
 */
final class SubscribedData {

    private final PlayerCounters counters;
    private final Odometry decodedOdometry = new Odometry();
    private final Odometry odometry = new Odometry();
    private final LaserData laserData;
    private final LaserScan decodedScan;
    private final LaserScan laserScan;
    private final RangerData rangerData;
    private final LaserScan rangerScan;
    private long odometryUpdates;
    private long laserUpdates;
    private long rangerUpdates;
    private int odometryIndex;
    private int laserIndex;
    private int rangerIndex;
    private RangerConfig rangerConfig;
    private long synchs;
    private String lastProtocolError;

    SubscribedData(PlayerCounters counters, int scanCapacity) {
        this.counters = counters;
        this.laserData = new LaserData(scanCapacity);
        this.decodedScan = new LaserScan(scanCapacity);
        this.laserScan = new LaserScan(scanCapacity);
        this.rangerData = new RangerData(scanCapacity);
        this.rangerScan = new LaserScan(scanCapacity);
    }

    /** Keeps the data of this device index from now on (position2d, laser and ranger). */
    void subscribed(int interf, int index) {
        switch (interf) {
            case Interfaces.POSITION2D -> odometryIndex = index;
            case Interfaces.LASER -> laserIndex = index;
            case Interfaces.RANGER -> rangerIndex = index;
            default -> {
                // other interfaces: subscribed, their data is counted as skipped
            }
        }
    }

    /** Converts this ranger's ranges with {@code config} from now on. */
    void rangerConfigured(int index, RangerConfig config) {
        if (index == rangerIndex) {
            rangerConfig = config;
        }
    }

    /** Handles a message that is not an awaited reply; its body is {@code body}. */
    void dispatch(PlayerHeader h, XdrReader body) {
        try {
            switch (h.type()) {
                case MessageType.DATA -> dispatchData(h, body);
                case MessageType.SYNCH -> {
                    synchs++;
                    counters.synchs++;
                }
                case MessageType.RESP_ACK -> {
                    if (!(h.interf() == Interfaces.PLAYER && h.subtype() == Subtypes.PLAYER_REQ_DATA)) {
                        counters.skippedMessages++;
                    }
                }
                default -> counters.skippedMessages++;
            }
        } catch (PlayerProtocolException e) {
            counters.protocolErrors++;
            lastProtocolError = e.getMessage();
        }
    }

    private void dispatchData(PlayerHeader h, XdrReader body) throws PlayerProtocolException {
        if (h.interf() == Interfaces.POSITION2D && h.subtype() == Subtypes.POSITION2D_DATA_STATE
                && h.index() == odometryIndex) {
            PlayerCodec.readPosition2dState(body, decodedOdometry);
            decodedOdometry.serverTimeS = h.timestampS();
            counters.odometryMessages++;
            if (counters.odometryChecks().acceptOdometry(decodedOdometry)) {
                odometry.copyFrom(decodedOdometry);
                odometryUpdates++;
            }
        } else if (h.interf() == Interfaces.LASER && h.subtype() == Subtypes.LASER_DATA_SCAN
                && h.index() == laserIndex) {
            PlayerCodec.readLaserScan(body, laserData);
            laserData.toLaserScan(decodedScan, h.timestampS());
            counters.scanMessages++;
            if (counters.laserChecks().acceptScan(decodedScan)) {
                laserScan.copyFrom(decodedScan);
                laserUpdates++;
            }
        } else if (h.interf() == Interfaces.RANGER && h.subtype() == Subtypes.RANGER_DATA_RANGE
                && h.index() == rangerIndex && rangerConfig != null) {
            PlayerCodec.readRangerData(body, rangerData);
            rangerData.toLaserScan(decodedScan, rangerConfig, h.timestampS());
            counters.scanMessages++;
            if (counters.rangerChecks().acceptScan(decodedScan)) {
                rangerScan.copyFrom(decodedScan);
                rangerUpdates++;
            }
        } else {
            counters.skippedMessages++;
        }
    }

    Odometry odometry() {
        return odometry;
    }

    long odometryUpdates() {
        return odometryUpdates;
    }

    LaserScan laserScan() {
        return laserScan;
    }

    long laserUpdates() {
        return laserUpdates;
    }

    LaserScan rangerScan() {
        return rangerScan;
    }

    long rangerUpdates() {
        return rangerUpdates;
    }

    long synchs() {
        return synchs;
    }

    String lastProtocolError() {
        return lastProtocolError;
    }
}
