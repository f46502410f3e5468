package io.rtaware.sim.server;

import io.rtaware.player.protocol.Interfaces;
import io.rtaware.player.protocol.PlayerCodec;
import io.rtaware.player.protocol.PlayerHeader;
import io.rtaware.player.protocol.SimulationPose2d;
import io.rtaware.player.protocol.Subtypes;
import io.rtaware.player.xdr.PlayerProtocolException;
import io.rtaware.player.xdr.XdrReader;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.sim.world.World;

/**
 * {@code simulation:0}: GET_POSE2D (ground truth) and SET_POSE2D of the one model the server
 * knows by name; other names and non-finite poses are NACKed. Thread-safe.
 */
final class SimulationDevice implements DeviceHandler {

    private final SharedWorld world;
    private final MessageFactory messages;
    private final String modelName;

    SimulationDevice(SharedWorld world, MessageFactory messages, String modelName) {
        this.world = world;
        this.messages = messages;
        this.modelName = modelName;
    }

    @Override
    public int interf() {
        return Interfaces.SIMULATION;
    }

    @Override
    public String driverName() {
        return PlayerSimServer.STAGE_DRIVER;
    }

    @Override
    public void request(ClientSession client, PlayerHeader h, XdrReader body) throws PlayerProtocolException {
        if (h.subtype() != Subtypes.SIMULATION_REQ_GET_POSE2D && h.subtype() != Subtypes.SIMULATION_REQ_SET_POSE2D) {
            client.reply(messages.nack(h));
            return;
        }
        SimulationPose2d req = PlayerCodec.readSimulationPose2d(body);
        if (!modelName.equals(req.name())) {
            client.reply(messages.nack(h));
            return;
        }
        if (h.subtype() == Subtypes.SIMULATION_REQ_SET_POSE2D) {
            if (!Double.isFinite(req.xM()) || !Double.isFinite(req.yM()) || !Double.isFinite(req.yawRad())) {
                client.reply(messages.nack(h));
                return;
            }
            world.update(w -> w.setPose(new Pose2d(req.xM(), req.yM(), req.yawRad())));
            client.reply(messages.ack(h, MessageFactory.Body.EMPTY));
        } else {
            Pose2d p = world.read(World::pose);
            client.reply(messages.ack(h, w -> PlayerCodec.writeSimulationPose2d(w,
                    new SimulationPose2d(req.name(), p.xM(), p.yM(), p.yawRad()))));
        }
    }
}
