package io.rtaware.sim.server;

import io.rtaware.player.protocol.Banner;
import io.rtaware.player.protocol.DeviceAddress;
import io.rtaware.player.protocol.Interfaces;
import io.rtaware.player.protocol.MessageType;
import io.rtaware.player.protocol.PlayerCodec;
import io.rtaware.player.protocol.PlayerHeader;
import io.rtaware.player.protocol.Subtypes;
import io.rtaware.player.xdr.XdrWriter;
import java.util.function.DoubleSupplier;

/**
 * Encodes what the server sends: replies carry the request's device with the server's host and
 * robot (port) fields and the current simulation time; data carries the step's time. Also the
 * banner and the SYNCH messages. Thread-safe (immutable).
 */
final class MessageFactory {

    /** Writes a message body. */
    interface Body {
        /** Nothing: an empty body. */
        Body EMPTY = w -> { };

        void write(XdrWriter w);
    }

    private final long host;
    private final long robot;
    private final DoubleSupplier simTimeS;
    private final byte[] banner;
    private final byte[] synchOk;

    /**
     * @param host the host field of every address (Player's host-order IPv4)
     * @param robot the robot field of every address (the port)
     * @param version the version the banner announces
     * @param simTimeS the time stamp of replies, in simulation seconds
     */
    MessageFactory(long host, long robot, String version, DoubleSupplier simTimeS) {
        this.host = host;
        this.robot = robot;
        this.simTimeS = simTimeS;
        this.banner = Banner.encode(version);
        XdrWriter w = new XdrWriter(64);
        int at = PlayerCodec.beginMessage(w, DeviceAddress.of(Interfaces.PLAYER, 0), MessageType.SYNCH,
                Subtypes.PLAYER_SYNCH_OK, 0.0);
        PlayerCodec.endMessage(w, at);
        this.synchOk = w.toByteArray();
    }

    /** @return the 32-byte banner every client gets first */
    byte[] banner() {
        return banner.clone();
    }

    /** @return SYNCH OK, which ends a PULL round */
    byte[] synchOk() {
        return synchOk.clone();
    }

    /**
     * @param interf an interface code
     * @return device {@code interf:0} of this server
     */
    DeviceAddress address(int interf) {
        return new DeviceAddress(host, robot, interf, 0);
    }

    /**
     * @param interf an interface code
     * @param index a device index
     * @return that device of this server
     */
    DeviceAddress address(int interf, int index) {
        return new DeviceAddress(host, robot, interf, index);
    }

    /**
     * @param request the request answered
     * @param body the reply's body
     * @return RESP_ACK to {@code request}
     */
    byte[] ack(PlayerHeader request, Body body) {
        return reply(request, MessageType.RESP_ACK, body);
    }

    /**
     * @param request the request refused
     * @return RESP_NACK to {@code request}, with an empty body
     */
    byte[] nack(PlayerHeader request) {
        return reply(request, MessageType.RESP_NACK, Body.EMPTY);
    }

    /**
     * @param request the request answered
     * @param type {@link MessageType#RESP_ACK} or {@link MessageType#RESP_NACK}
     * @param body the reply's body
     * @return the reply: the request's device and subtype, the given type, simulation time
     */
    byte[] reply(PlayerHeader request, int type, Body body) {
        XdrWriter w = new XdrWriter(256);
        int at = PlayerCodec.beginMessage(w, address(request.interf(), request.index()), type, request.subtype(),
                simTimeS.getAsDouble());
        body.write(w);
        PlayerCodec.endMessage(w, at);
        return w.toByteArray();
    }

    /**
     * @param interf the publishing device's interface ({@code interf:0})
     * @param subtype the data subtype
     * @param timeS the time stamp, simulation seconds
     * @param capacityBytes a guess of the encoded size
     * @param body the data
     * @return the DATA message
     */
    Outgoing data(int interf, int subtype, double timeS, int capacityBytes, Body body) {
        XdrWriter w = new XdrWriter(capacityBytes);
        int at = PlayerCodec.beginMessage(w, address(interf), MessageType.DATA, subtype, timeS);
        body.write(w);
        PlayerCodec.endMessage(w, at);
        return new Outgoing(w.toByteArray(), interf, 0, MessageType.DATA, subtype);
    }

    /**
     * @param dropped data messages dropped since the last round
     * @return SYNCH OVERFLOW carrying the count
     */
    static byte[] synchOverflow(long dropped) {
        XdrWriter w = new XdrWriter(64);
        int at = PlayerCodec.beginMessage(w, DeviceAddress.of(Interfaces.PLAYER, 0), MessageType.SYNCH,
                Subtypes.PLAYER_SYNCH_OVERFLOW, 0.0);
        PlayerCodec.writeSynchOverflow(w, dropped);
        PlayerCodec.endMessage(w, at);
        return w.toByteArray();
    }
}
