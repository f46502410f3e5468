package io.rtaware.sim.server;

import io.rtaware.player.protocol.Interfaces;
import io.rtaware.player.protocol.PlayerCodec;
import io.rtaware.player.protocol.PlayerHeader;
import io.rtaware.player.protocol.RangerConfig;
import io.rtaware.player.protocol.RangerData;
import io.rtaware.player.protocol.RangerGeometry;
import io.rtaware.player.protocol.Subtypes;
import io.rtaware.player.xdr.XdrReader;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.sim.world.World;
import java.util.List;

/**
 * {@code ranger:0} (the laser as Stage's ranger model): DATA RANGE and DATA INTNS per sensor
 * update, GET_GEOM and GET_CONFIG. Requests are thread-safe; {@link #publish} reuses one buffer
 * and runs on the stepping thread only.
 */
final class RangerDevice implements DeviceHandler {

    private final SharedWorld world;
    private final MessageFactory messages;
    private final RangerData values;

    RangerDevice(SharedWorld world, MessageFactory messages) {
        this.world = world;
        this.messages = messages;
        this.values = new RangerData(world.laserConfig().beams());
    }

    /** @return a beam's intensity as Stage reports it: 1 if it hit something, else 0 */
    static byte intensity(LaserScan scan, int beam) {
        return (byte) (scan.rangesM[beam] < scan.maxRangeM ? 1 : 0);
    }

    @Override
    public int interf() {
        return Interfaces.RANGER;
    }

    @Override
    public String driverName() {
        return PlayerSimServer.STAGE_DRIVER;
    }

    @Override
    public void request(ClientSession client, PlayerHeader h, XdrReader body) {
        io.rtaware.sim.world.LaserConfig c = world.laserConfig();
        switch (h.subtype()) {
            case Subtypes.RANGER_REQ_GET_GEOM -> client.reply(messages.ack(h,
                    w -> PlayerCodec.writeRangerGeometry(w, new RangerGeometry(LaserDevice.GEOMETRY.pose(),
                            LaserDevice.GEOMETRY.size(), List.of(LaserDevice.GEOMETRY.pose()),
                            List.of(LaserDevice.GEOMETRY.size())))));
            case Subtypes.RANGER_REQ_GET_CONFIG -> client.reply(messages.ack(h,
                    w -> PlayerCodec.writeRangerConfig(w, new RangerConfig(c.minAngleRad(), c.maxAngleRad(),
                            c.angleIncrementRad(), c.minRangeM(), c.maxRangeM(), 0.001, c.rateHz()))));
            default -> client.reply(messages.nack(h));
        }
    }

    @Override
    public void publish(World w, double timeS, List<Outgoing> out) {
        if (!w.scanFresh()) {
            return;
        }
        LaserScan scan = w.scan();
        int n = scan.count();
        values.count = n;
        for (int i = 0; i < n; i++) {
            values.values[i] = scan.rangesM[i];
        }
        out.add(messages.data(Interfaces.RANGER, Subtypes.RANGER_DATA_RANGE, timeS, 16 * n + 128,
                xdr -> PlayerCodec.writeRangerData(xdr, values)));
        for (int i = 0; i < n; i++) {
            values.values[i] = intensity(scan, i);
        }
        out.add(messages.data(Interfaces.RANGER, Subtypes.RANGER_DATA_INTNS, timeS, 8 * n + 128,
                xdr -> PlayerCodec.writeRangerData(xdr, values)));
    }
}
