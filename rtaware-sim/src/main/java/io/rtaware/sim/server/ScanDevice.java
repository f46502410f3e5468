package io.rtaware.sim.server;

import io.rtaware.player.protocol.Bbox3d;
import io.rtaware.player.protocol.Geometry;
import io.rtaware.player.protocol.PlayerHeader;
import io.rtaware.player.protocol.Pose3d;
import io.rtaware.player.xdr.XdrReader;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.sim.world.LaserConfig;
import io.rtaware.sim.world.World;
import java.util.List;

/**
 * What the simulator's two views of its laser share, {@code laser:0} ({@link LaserDevice}) and
 * Stage's {@code ranger:0} ({@link RangerDevice}): the same mounting, the two requests each
 * interface answers (its geometry, its configuration), and one publication per fresh scan.
 * Requests are thread-safe; {@link #publish} reuses its device's buffer and runs on the stepping
 * thread only.
 */
abstract sealed class ScanDevice implements DeviceHandler permits LaserDevice, RangerDevice {

    /** The laser's mounting (robot centre) and size (URG-04LX: 50 x 50 x 70 mm). */
    static final Geometry GEOMETRY = new Geometry(new Pose3d(0, 0, 0, 0, 0, 0), new Bbox3d(0.05, 0.05, 0.07));

    final SharedWorld world;
    final MessageFactory messages;
    private final int interf;
    private final String driver;
    private final int geometryRequest;
    private final int configRequest;

    /**
     * @param world the world whose laser it serves
     * @param messages where its replies and data are made
     * @param interf its Player interface
     * @param driver the driver name it reports
     * @param geometryRequest the interface's GET_GEOM subtype
     * @param configRequest the interface's GET_CONFIG subtype
     */
    ScanDevice(SharedWorld world, MessageFactory messages, int interf, String driver, int geometryRequest,
               int configRequest) {
        this.world = world;
        this.messages = messages;
        this.interf = interf;
        this.driver = driver;
        this.geometryRequest = geometryRequest;
        this.configRequest = configRequest;
    }

    /** @return a beam's intensity as Stage reports it: 1 if it hit something, else 0 */
    static byte intensity(LaserScan scan, int beam) {
        return (byte) (scan.rangesM[beam] < scan.maxRangeM ? 1 : 0);
    }

    @Override
    public final int interf() {
        return interf;
    }

    @Override
    public final String driverName() {
        return driver;
    }

    @Override
    public final void request(ClientSession client, PlayerHeader h, XdrReader body) {
        LaserConfig c = world.laserConfig();
        if (h.subtype() == geometryRequest) {
            client.reply(messages.ack(h, geometry()));
        } else if (h.subtype() == configRequest) {
            client.reply(messages.ack(h, config(c)));
        } else {
            client.reply(messages.nack(h));
        }
    }

    @Override
    public final void publish(World w, double timeS, List<Outgoing> out) {
        if (w.scanFresh()) {
            publish(w.scan(), w.laserConfig(), timeS, out);
        }
    }

    /** @return the body of the reply to GET_GEOM: {@link #GEOMETRY} in this interface's form */
    abstract MessageFactory.Body geometry();

    /**
     * @param c the laser's configuration
     * @return the body of the reply to GET_CONFIG
     */
    abstract MessageFactory.Body config(LaserConfig c);

    /**
     * Adds the DATA messages of a fresh scan.
     *
     * @param scan the scan
     * @param c the laser's configuration
     * @param timeS the messages' time stamp, simulation seconds
     * @param out where they go
     */
    abstract void publish(LaserScan scan, LaserConfig c, double timeS, List<Outgoing> out);
}
