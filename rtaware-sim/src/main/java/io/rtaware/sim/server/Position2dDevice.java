package io.rtaware.sim.server;

import io.rtaware.player.protocol.Bbox3d;
import io.rtaware.player.protocol.Geometry;
import io.rtaware.player.protocol.Interfaces;
import io.rtaware.player.protocol.PlayerCodec;
import io.rtaware.player.protocol.PlayerHeader;
import io.rtaware.player.protocol.Pose3d;
import io.rtaware.player.protocol.Subtypes;
import io.rtaware.player.protocol.VelocityCmd;
import io.rtaware.player.xdr.PlayerProtocolException;
import io.rtaware.player.xdr.XdrReader;
import io.rtaware.sim.world.World;
import java.util.List;

/**
 * {@code position2d:0}: DATA STATE (odometry) at the odometry rate, CMD VEL, GET_GEOM (the
 * robot's footprint) and MOTOR_POWER. Thread-safe.
 */
final class Position2dDevice implements DeviceHandler {

    private final SharedWorld world;
    private final MessageFactory messages;

    Position2dDevice(SharedWorld world, MessageFactory messages) {
        this.world = world;
        this.messages = messages;
    }

    @Override
    public int interf() {
        return Interfaces.POSITION2D;
    }

    @Override
    public String driverName() {
        return PlayerSimServer.STAGE_DRIVER;
    }

    @Override
    public void request(ClientSession client, PlayerHeader h, XdrReader body) throws PlayerProtocolException {
        switch (h.subtype()) {
            case Subtypes.POSITION2D_REQ_GET_GEOM -> {
                double d = 2 * world.robotConfig().radiusM();
                client.reply(messages.ack(h, w -> PlayerCodec.writeGeometry(w,
                        new Geometry(new Pose3d(0, 0, 0, 0, 0, 0), new Bbox3d(d, d, 0)))));
            }
            case Subtypes.POSITION2D_REQ_MOTOR_POWER -> {
                boolean on = PlayerCodec.readMotorPower(body);
                world.update(wd -> wd.setMotorsEnabled(on));
                client.reply(messages.ack(h, MessageFactory.Body.EMPTY));
            }
            default -> client.reply(messages.nack(h));
        }
    }

    @Override
    public void command(PlayerHeader h, XdrReader body) throws PlayerProtocolException {
        if (h.subtype() == Subtypes.POSITION2D_CMD_VEL) {
            VelocityCmd c = PlayerCodec.readVelocityCmd(body);
            world.update(wd -> wd.command(c.vxMps(), c.omegaRadPerSec()));
        }
    }

    @Override
    public void publish(World w, double timeS, List<Outgoing> out) {
        if (w.odometryFresh()) {
            out.add(messages.data(Interfaces.POSITION2D, Subtypes.POSITION2D_DATA_STATE, timeS, 128,
                    xdr -> PlayerCodec.writePosition2dState(xdr, w.odometry())));
        }
    }
}
