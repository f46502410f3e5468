package io.rtaware.sim.server;

import io.rtaware.player.protocol.PlayerHeader;
import io.rtaware.player.xdr.PlayerProtocolException;
import io.rtaware.player.xdr.XdrReader;
import io.rtaware.sim.world.World;
import java.util.List;

/**
 * One device the simulator serves at index 0: its requests, its commands and the data it
 * publishes after a world step. {@link RequestRouter} routes a client's messages here;
 * {@link WorldStepper} asks for data. Implementations are thread-safe for requests and commands
 * (reader threads of several clients); {@link #publish} runs on the stepping thread only.
 */
interface DeviceHandler {

    /** @return the Player interface code (the device is {@code interf:0}) */
    int interf();

    /** @return the driver name DRIVERINFO and DEV report */
    String driverName();

    /**
     * Answers one REQ to this device: exactly one ACK or NACK to {@code client}.
     *
     * @param client who asked
     * @param request the header
     * @param body the body
     * @throws PlayerProtocolException if the body is malformed (the client is disconnected)
     */
    void request(ClientSession client, PlayerHeader request, XdrReader body) throws PlayerProtocolException;

    /**
     * Applies one CMD; commands a device does not know are ignored, as Player does.
     *
     * @param command the header
     * @param body the body
     * @throws PlayerProtocolException if the body is malformed (the client is disconnected)
     */
    default void command(PlayerHeader command, XdrReader body) throws PlayerProtocolException {
    }

    /**
     * Adds the DATA messages of the step just taken (called under the world lock, only while a
     * client subscribes to this device).
     *
     * @param world the world, just stepped
     * @param timeS its time, simulation seconds (the messages' time stamp)
     * @param out where the messages go, in the order they are sent
     */
    default void publish(World world, double timeS, List<Outgoing> out) {
    }

    /**
     * @param interf an interface code
     * @param index a device index
     * @return the key subscriptions are kept under
     */
    static int key(int interf, int index) {
        return interf << 16 | index;
    }
}
