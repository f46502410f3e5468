package io.rtaware.sim.server;

import io.rtaware.player.protocol.Bbox3d;
import io.rtaware.player.protocol.Geometry;
import io.rtaware.player.protocol.Interfaces;
import io.rtaware.player.protocol.LaserConfig;
import io.rtaware.player.protocol.LaserData;
import io.rtaware.player.protocol.PlayerCodec;
import io.rtaware.player.protocol.PlayerHeader;
import io.rtaware.player.protocol.Pose3d;
import io.rtaware.player.protocol.Subtypes;
import io.rtaware.player.xdr.XdrReader;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.sim.world.World;
import java.util.List;

/**
 * {@code laser:0}: DATA SCAN once per sensor update (Player's rangertolaser publishes two),
 * GET_GEOM and GET_CONFIG. Requests are thread-safe; {@link #publish} reuses one buffer and runs
 * on the stepping thread only.
 */
final class LaserDevice implements DeviceHandler {

    /** The laser's mounting (robot centre) and size (URG-04LX: 50 x 50 x 70 mm). */
    static final Geometry GEOMETRY = new Geometry(new Pose3d(0, 0, 0, 0, 0, 0), new Bbox3d(0.05, 0.05, 0.07));

    private final SharedWorld world;
    private final MessageFactory messages;
    private final LaserData scanData;

    LaserDevice(SharedWorld world, MessageFactory messages) {
        this.world = world;
        this.messages = messages;
        this.scanData = new LaserData(world.laserConfig().beams());
    }

    @Override
    public int interf() {
        return Interfaces.LASER;
    }

    @Override
    public String driverName() {
        return PlayerSimServer.LASER_DRIVER;
    }

    @Override
    public void request(ClientSession client, PlayerHeader h, XdrReader body) {
        io.rtaware.sim.world.LaserConfig c = world.laserConfig();
        switch (h.subtype()) {
            case Subtypes.LASER_REQ_GET_GEOM -> client.reply(messages.ack(h, w -> PlayerCodec.writeGeometry(w, GEOMETRY)));
            case Subtypes.LASER_REQ_GET_CONFIG -> client.reply(messages.ack(h,
                    w -> PlayerCodec.writeLaserConfig(w, new LaserConfig((float) c.minAngleRad(),
                            (float) c.maxAngleRad(), (float) c.angleIncrementRad(), (float) c.maxRangeM(),
                            0.001f, 1, (float) c.rateHz()))));
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
        scanData.minAngleRad = (float) scan.minAngleRad;
        scanData.maxAngleRad = (float) scan.maxAngleRad;
        scanData.resolutionRad = (float) w.laserConfig().angleIncrementRad();
        scanData.maxRangeM = (float) scan.maxRangeM;
        System.arraycopy(scan.rangesM, 0, scanData.rangesM, 0, n);
        scanData.rangeCount = n;
        for (int i = 0; i < n; i++) {
            scanData.intensities[i] = RangerDevice.intensity(scan, i);
        }
        scanData.intensityCount = n;
        scanData.id = 0;
        out.add(messages.data(Interfaces.LASER, Subtypes.LASER_DATA_SCAN, timeS, 5 * n + 128,
                xdr -> PlayerCodec.writeLaserScan(xdr, scanData)));
    }
}
