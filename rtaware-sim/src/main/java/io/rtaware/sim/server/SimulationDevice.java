package io.rtaware.sim.server;

import io.rtaware.player.protocol.Interfaces;
import io.rtaware.player.protocol.PlayerCodec;
import io.rtaware.player.protocol.PlayerHeader;
import io.rtaware.player.protocol.SimulationPose2d;
import io.rtaware.player.protocol.Subtypes;
import io.rtaware.player.xdr.PlayerProtocolException;
import io.rtaware.player.xdr.XdrReader;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.sim.actor.Actors;
import io.rtaware.sim.world.World;

/**
 * {@code simulation:0}: GET_POSE2D (ground truth) and SET_POSE2D of the robot's model by name,
 * GET_POSE2D of the scenario's actors by their names (as Stage answers for any model of its
 * world; they cannot be moved); other names and non-finite poses are NACKed. Thread-safe.
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

    /** An actor's pose (x, y, heading along its motion, 0 while it stands), or null for no such actor. */
    private static double[] actorPose(World w, String name) {
        Actors actors = w.actors();
        int i = actors.indexOf(name);
        if (i < 0) {
            return null;
        }
        double vx = actors.vxMps(i);
        double vy = actors.vyMps(i);
        return new double[] {actors.xM(i), actors.yM(i), vx == 0 && vy == 0 ? 0.0 : Math.atan2(vy, vx)};
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
            double[] actor = h.subtype() == Subtypes.SIMULATION_REQ_GET_POSE2D ? world.read(w -> actorPose(w, req.name())) : null;
            if (actor == null) {
                client.reply(messages.nack(h));
                return;
            }
            client.reply(messages.ack(h, w -> PlayerCodec.writeSimulationPose2d(w,
                    new SimulationPose2d(req.name(), actor[0], actor[1], actor[2]))));
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
