package io.rtaware.sim.server;

import io.rtaware.player.protocol.Interfaces;
import io.rtaware.player.protocol.LaserData;
import io.rtaware.player.protocol.PlayerCodec;
import io.rtaware.player.protocol.Subtypes;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.sim.world.LaserConfig;
import java.util.List;

/**
 * {@code laser:0}: DATA SCAN once per sensor update (Player's rangertolaser publishes two),
 * GET_GEOM and GET_CONFIG.
 */
final class LaserDevice extends ScanDevice {

    private final LaserData scanData;

    LaserDevice(SharedWorld world, MessageFactory messages) {
        super(world, messages, Interfaces.LASER, PlayerSimServer.LASER_DRIVER, Subtypes.LASER_REQ_GET_GEOM,
                Subtypes.LASER_REQ_GET_CONFIG);
        this.scanData = new LaserData(world.laserConfig().beams());
    }

    @Override
    MessageFactory.Body geometry() {
        return w -> PlayerCodec.writeGeometry(w, GEOMETRY);
    }

    @Override
    MessageFactory.Body config(LaserConfig c) {
        return w -> PlayerCodec.writeLaserConfig(w, new io.rtaware.player.protocol.LaserConfig((float) c.minAngleRad(),
                (float) c.maxAngleRad(), (float) c.angleIncrementRad(), (float) c.maxRangeM(), 0.001f, 1,
                (float) c.rateHz()));
    }

    @Override
    void publish(LaserScan scan, LaserConfig c, double timeS, List<Outgoing> out) {
        int n = scan.count();
        scanData.minAngleRad = (float) scan.minAngleRad;
        scanData.maxAngleRad = (float) scan.maxAngleRad;
        scanData.resolutionRad = (float) c.angleIncrementRad();
        scanData.maxRangeM = (float) scan.maxRangeM;
        System.arraycopy(scan.rangesM, 0, scanData.rangesM, 0, n);
        scanData.rangeCount = n;
        for (int i = 0; i < n; i++) {
            scanData.intensities[i] = intensity(scan, i);
        }
        scanData.intensityCount = n;
        scanData.id = 0;
        out.add(messages.data(Interfaces.LASER, Subtypes.LASER_DATA_SCAN, timeS, 5 * n + 128,
                xdr -> PlayerCodec.writeLaserScan(xdr, scanData)));
    }
}
