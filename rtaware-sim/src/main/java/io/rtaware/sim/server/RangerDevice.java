package io.rtaware.sim.server;

import io.rtaware.player.protocol.Interfaces;
import io.rtaware.player.protocol.PlayerCodec;
import io.rtaware.player.protocol.RangerConfig;
import io.rtaware.player.protocol.RangerData;
import io.rtaware.player.protocol.RangerGeometry;
import io.rtaware.player.protocol.Subtypes;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.sim.world.LaserConfig;
import java.util.List;

/**
 * {@code ranger:0} (the laser as Stage's ranger model): DATA RANGE and DATA INTNS per sensor
 * update, GET_GEOM and GET_CONFIG.
 */
final class RangerDevice extends ScanDevice {

    private final RangerData values;

    RangerDevice(SharedWorld world, MessageFactory messages) {
        super(world, messages, Interfaces.RANGER, PlayerSimServer.STAGE_DRIVER, Subtypes.RANGER_REQ_GET_GEOM,
                Subtypes.RANGER_REQ_GET_CONFIG);
        this.values = new RangerData(world.laserConfig().beams());
    }

    @Override
    MessageFactory.Body geometry() {
        return w -> PlayerCodec.writeRangerGeometry(w, new RangerGeometry(GEOMETRY.pose(), GEOMETRY.size(),
                List.of(GEOMETRY.pose()), List.of(GEOMETRY.size())));
    }

    @Override
    MessageFactory.Body config(LaserConfig c) {
        return w -> PlayerCodec.writeRangerConfig(w, new RangerConfig(c.minAngleRad(), c.maxAngleRad(),
                c.angleIncrementRad(), c.minRangeM(), c.maxRangeM(), 0.001, c.rateHz()));
    }

    @Override
    void publish(LaserScan scan, LaserConfig c, double timeS, List<Outgoing> out) {
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
