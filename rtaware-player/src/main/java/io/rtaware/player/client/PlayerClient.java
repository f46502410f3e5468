package io.rtaware.player.client;

import io.rtaware.player.protocol.DeviceAddress;
import io.rtaware.player.protocol.DeviceRequest;
import io.rtaware.player.protocol.DriverInfo;
import io.rtaware.player.protocol.Geometry;
import io.rtaware.player.protocol.Interfaces;
import io.rtaware.player.protocol.LaserConfig;
import io.rtaware.player.protocol.MessageType;
import io.rtaware.player.protocol.PlayerCodec;
import io.rtaware.player.protocol.PlayerHeader;
import io.rtaware.player.protocol.RangerConfig;
import io.rtaware.player.protocol.RangerGeometry;
import io.rtaware.player.protocol.ReplaceRule;
import io.rtaware.player.protocol.SimulationPose2d;
import io.rtaware.player.protocol.Subtypes;
import io.rtaware.player.xdr.PlayerProtocolException;
import io.rtaware.player.xdr.XdrWriter;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.robot.validate.SampleChecks;
import io.rtaware.robot.validate.SampleLimits;
import java.io.Closeable;
import java.io.IOException;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * A client of one Player server over TCP: the typed requests and the data of one session.
 * {@link #connect} opens the connection and checks the banner ({@link PlayerConnection});
 * requests ({@link #deviceList()}, {@link #subscribe}, {@link #laserConfig} ...) block until the
 * matching reply or the request timeout ({@link RequestChannel}); {@link #poll} reads what the
 * server sends. Data that arrives while waiting for a reply is kept like data read by
 * {@link #poll} ({@link SubscribedData}): the newest position2d state in {@link #odometry()},
 * the newest laser scan in {@link #laserScan()} and the newest ranger ranges, converted with the
 * ranger's configuration (fetched by {@link #rangerConfig}), in {@link #rangerScan()}. A sample
 * that cannot be true ({@link SampleChecks}) is counted as rejected in {@link PlayerCounters} and
 * never kept. Messages of other interfaces or subtypes are skipped and counted; a malformed data
 * body is counted as a protocol error and skipped; a broken stream (bad header, stream ended
 * inside a message) is thrown as {@link PlayerProtocolException}, after which the client must be
 * closed.
 *
 * <p>Not thread-safe: one thread owns a client. Its {@link PlayerCounters} may be read from
 * any thread.
 */
public final class PlayerClient implements Closeable {

    private static final int PLAYER_INDEX = 0;

    private final PlayerConnection connection;
    private final PlayerCounters counters;
    private final SubscribedData data;
    private final RequestChannel requests;
    private final DeviceAddress playerAddress = DeviceAddress.of(Interfaces.PLAYER, PLAYER_INDEX);

    private PlayerClient(PlayerConnection connection, PlayerClientOptions options, PlayerCounters counters) {
        this.connection = connection;
        this.counters = counters;
        this.data = new SubscribedData(counters, options.scanCapacity());
        this.requests = new RequestChannel(connection, data, options.requestTimeoutMs());
    }

    /**
     * Connects and reads the banner. The server starts in PUSH mode.
     *
     * @param host server host
     * @param port server port
     * @param options timeouts and limits
     * @param counters where to count traffic and rejected samples (shared across reconnections)
     * @return the connected client
     * @throws PlayerConnectionException if the server cannot be reached in time
     * @throws PlayerProtocolException if the peer is not a Player server (the message shows
     *     what it sent)
     * @throws IOException on other I/O failures
     */
    public static PlayerClient connect(String host, int port, PlayerClientOptions options, PlayerCounters counters)
            throws IOException {
        return new PlayerClient(PlayerConnection.open(host, port, options, counters), options, counters);
    }

    /** @return the version the server announced, e.g. {@code 3.1.1-dev} */
    public String serverVersion() {
        return connection.serverVersion();
    }

    /** @return {@code host:port} of the server */
    public String server() {
        return connection.server();
    }

    /** @return the counters this client updates */
    public PlayerCounters counters() {
        return counters;
    }

    // ---------------------------------------------------------------- commands

    private DeviceAddress deviceAddress(int interf, int index) {
        // libplayerc sends host 0 and robot = port for device messages; the server ignores both
        return new DeviceAddress(0, connection.port(), interf, index);
    }

    private XdrWriter writer() {
        return connection.writer();
    }

    /**
     * Sends position2d CMD VEL (never answered).
     *
     * @param index position2d device index
     * @param vxMps forward speed
     * @param vyMps sideways speed
     * @param omegaRadPerSec turn rate
     * @param state motor state (1 = on, as Player's C client sends)
     * @throws IOException if the connection fails
     */
    public void sendVelocity(int index, double vxMps, double vyMps, double omegaRadPerSec, int state)
            throws IOException {
        int at = connection.begin(deviceAddress(Interfaces.POSITION2D, index), MessageType.CMD,
                Subtypes.POSITION2D_CMD_VEL);
        PlayerCodec.writeVelocityCmd(writer(), vxMps, vyMps, omegaRadPerSec, state);
        connection.send(at);
        counters.commandsSent++;
    }

    /**
     * PULL mode: asks for one round of data without waiting; {@link #poll} with
     * {@code untilSynch} then reads the acknowledgement, the data and the closing SYNCH.
     *
     * @throws IOException if the connection fails
     */
    public void requestData() throws IOException {
        connection.send(connection.begin(playerAddress, MessageType.REQ, Subtypes.PLAYER_REQ_DATA));
    }

    /**
     * Reads what the server sends, keeping the newest data. Returns when {@code waitMs} has
     * passed, or (with {@code untilSynch}) when a SYNCH arrived, or (without) when at least one
     * message was read and nothing more is waiting in the socket.
     *
     * @param waitMs longest wall time to wait
     * @param untilSynch true in PULL mode: read until the end of the round
     * @return messages read
     * @throws PlayerConnectionException if the connection was lost
     * @throws PlayerProtocolException if the stream is broken
     * @throws IOException on other I/O failures
     */
    public int poll(int waitMs, boolean untilSynch) throws IOException {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(waitMs);
        long synchsBefore = data.synchs();
        int n = 0;
        while (true) {
            long leftNs = deadline - System.nanoTime();
            if (leftNs <= 0) {
                return n;
            }
            PlayerHeader h = connection.readOne(leftNs);
            if (h == null) {
                return n;
            }
            n++;
            data.dispatch(h, connection.body());
            if (untilSynch ? data.synchs() != synchsBefore : connection.available() == 0) {
                return n;
            }
        }
    }

    // ---------------------------------------------------------------- requests

    /**
     * Switches between PUSH and PULL.
     *
     * @param mode {@link Subtypes#DATAMODE_PUSH} or {@link Subtypes#DATAMODE_PULL}
     * @throws IOException on timeout, refusal or connection failure
     */
    public void setDataMode(int mode) throws IOException {
        int at = connection.begin(playerAddress, MessageType.REQ, Subtypes.PLAYER_REQ_DATAMODE);
        PlayerCodec.writeDataMode(writer(), mode);
        requests.request(playerAddress, Subtypes.PLAYER_REQ_DATAMODE, "REQ DATAMODE", at);
    }

    /**
     * Adds a replace rule to this connection's queue on the server.
     *
     * @param rule the rule, e.g. {@link ReplaceRule#latestDataOnly()}
     * @throws IOException on timeout, refusal or connection failure
     */
    public void addReplaceRule(ReplaceRule rule) throws IOException {
        int at = connection.begin(playerAddress, MessageType.REQ, Subtypes.PLAYER_REQ_ADD_REPLACE_RULE);
        PlayerCodec.writeReplaceRule(writer(), rule);
        requests.request(playerAddress, Subtypes.PLAYER_REQ_ADD_REPLACE_RULE, "REQ ADD_REPLACE_RULE", at);
    }

    /**
     * @return the server's devices
     * @throws IOException on timeout, refusal, malformed reply or connection failure
     */
    public List<DeviceAddress> deviceList() throws IOException {
        int at = connection.begin(playerAddress, MessageType.REQ, Subtypes.PLAYER_REQ_DEVLIST);
        return PlayerCodec.readDeviceList(requests.request(playerAddress, Subtypes.PLAYER_REQ_DEVLIST, "REQ DEVLIST",
                at));
    }

    /**
     * @param device a device of the server
     * @return its driver's name
     * @throws IOException on timeout, refusal, malformed reply or connection failure
     */
    public String driverInfo(DeviceAddress device) throws IOException {
        int at = connection.begin(playerAddress, MessageType.REQ, Subtypes.PLAYER_REQ_DRIVERINFO);
        PlayerCodec.writeDriverInfo(writer(), new DriverInfo(device, ""));
        return PlayerCodec.readDriverInfo(requests.request(playerAddress, Subtypes.PLAYER_REQ_DRIVERINFO,
                "REQ DRIVERINFO for " + device, at)).driverName();
    }

    /**
     * Subscribes to a device; its data is kept from then on (position2d, laser and ranger
     * data of the subscribed index).
     *
     * @param device the device, e.g. {@code DeviceAddress.parse("laser:0")}
     * @return the reply: granted access and driver name
     * @throws PlayerNackException if the server has no such device or the driver refused
     * @throws IOException on timeout, malformed reply or connection failure
     */
    public DeviceRequest subscribe(DeviceAddress device) throws IOException {
        DeviceRequest reply = deviceRequest(device, Subtypes.ACCESS_OPEN);
        data.subscribed(device.interf(), device.index());
        return reply;
    }

    /**
     * @param device a subscribed device
     * @return the reply
     * @throws PlayerNackException if the server refused
     * @throws IOException on timeout, malformed reply or connection failure
     */
    public DeviceRequest unsubscribe(DeviceAddress device) throws IOException {
        return deviceRequest(device, Subtypes.ACCESS_CLOSE);
    }

    private DeviceRequest deviceRequest(DeviceAddress device, int access) throws IOException {
        String what = "REQ DEV " + Subtypes.accessName(access) + " for " + device;
        int at = connection.begin(playerAddress, MessageType.REQ, Subtypes.PLAYER_REQ_DEV);
        PlayerCodec.writeDeviceRequest(writer(), new DeviceRequest(DeviceAddress.of(device.interf(), device.index()),
                access, ""));
        connection.send(at);
        DeviceRequest reply = PlayerCodec.readDeviceRequest(requests.awaitReply(playerAddress,
                Subtypes.PLAYER_REQ_DEV, what, server() + " has no device " + device + " (RESP_NACK to " + what + ")"));
        if (reply.access() == Subtypes.ACCESS_ERROR) {
            throw new PlayerNackException(server() + " could not " + (access == Subtypes.ACCESS_OPEN
                    ? "subscribe to " : "unsubscribe from ") + device + ": driver '" + reply.driverName()
                    + "' answered access=ERROR");
        }
        return reply;
    }

    /**
     * @param index position2d index
     * @return the base's pose on the robot and size
     * @throws IOException on timeout, refusal, malformed reply or connection failure
     */
    public Geometry position2dGeometry(int index) throws IOException {
        DeviceAddress dev = deviceAddress(Interfaces.POSITION2D, index);
        int at = connection.begin(dev, MessageType.REQ, Subtypes.POSITION2D_REQ_GET_GEOM);
        return PlayerCodec.readGeometry(requests.request(dev, Subtypes.POSITION2D_REQ_GET_GEOM, "REQ GET_GEOM", at));
    }

    /**
     * @param index position2d index
     * @param on true to enable the motors
     * @throws IOException on timeout, refusal or connection failure
     */
    public void setMotorPower(int index, boolean on) throws IOException {
        DeviceAddress dev = deviceAddress(Interfaces.POSITION2D, index);
        int at = connection.begin(dev, MessageType.REQ, Subtypes.POSITION2D_REQ_MOTOR_POWER);
        PlayerCodec.writeMotorPower(writer(), on);
        requests.request(dev, Subtypes.POSITION2D_REQ_MOTOR_POWER, "REQ MOTOR_POWER", at);
    }

    /**
     * @param index laser index
     * @return the laser's pose on the robot and size
     * @throws IOException on timeout, refusal, malformed reply or connection failure
     */
    public Geometry laserGeometry(int index) throws IOException {
        DeviceAddress dev = deviceAddress(Interfaces.LASER, index);
        int at = connection.begin(dev, MessageType.REQ, Subtypes.LASER_REQ_GET_GEOM);
        return PlayerCodec.readGeometry(requests.request(dev, Subtypes.LASER_REQ_GET_GEOM, "REQ GET_GEOM", at));
    }

    /**
     * @param index laser index
     * @return the scan configuration
     * @throws IOException on timeout, refusal, malformed reply or connection failure
     */
    public LaserConfig laserConfig(int index) throws IOException {
        DeviceAddress dev = deviceAddress(Interfaces.LASER, index);
        int at = connection.begin(dev, MessageType.REQ, Subtypes.LASER_REQ_GET_CONFIG);
        return PlayerCodec.readLaserConfig(requests.request(dev, Subtypes.LASER_REQ_GET_CONFIG, "REQ GET_CONFIG",
                at));
    }

    /**
     * @param index ranger index
     * @return the ranger's geometry
     * @throws IOException on timeout, refusal, malformed reply or connection failure
     */
    public RangerGeometry rangerGeometry(int index) throws IOException {
        DeviceAddress dev = deviceAddress(Interfaces.RANGER, index);
        int at = connection.begin(dev, MessageType.REQ, Subtypes.RANGER_REQ_GET_GEOM);
        return PlayerCodec.readRangerGeometry(requests.request(dev, Subtypes.RANGER_REQ_GET_GEOM, "REQ GET_GEOM",
                at));
    }

    /**
     * Fetches the ranger's configuration and keeps it: ranger ranges are converted into
     * {@link #rangerScan()} with its angles and maximum range from then on. A configuration
     * whose angles or maximum range cannot be true ({@link SampleChecks#scanGeometry}) is
     * refused, so no scan is ever built on it.
     *
     * @param index ranger index
     * @return the configuration
     * @throws PlayerProtocolException if the configuration cannot be true
     * @throws IOException on timeout, refusal, malformed reply or connection failure
     */
    public RangerConfig rangerConfig(int index) throws IOException {
        DeviceAddress dev = deviceAddress(Interfaces.RANGER, index);
        int at = connection.begin(dev, MessageType.REQ, Subtypes.RANGER_REQ_GET_CONFIG);
        RangerConfig c = PlayerCodec.readRangerConfig(requests.request(dev, Subtypes.RANGER_REQ_GET_CONFIG,
                "REQ GET_CONFIG", at));
        String bad = SampleChecks.scanGeometry(c.minAngleRad(), c.maxAngleRad(), c.maxRangeM(),
                SampleLimits.defaults());
        if (bad != null) {
            counters.protocolErrors++;
            throw new PlayerProtocolException(0, "ranger.config", server() + " sent a ranger:" + index
                    + " configuration that cannot be true: " + bad);
        }
        data.rangerConfigured(index, c);
        return c;
    }

    /**
     * Asks the simulator for a model's pose (ground truth with Stage).
     *
     * @param index simulation index
     * @param model model name, e.g. {@code r0}
     * @return the model's pose
     * @throws IOException on timeout, refusal (e.g. unknown model), malformed reply or
     *     connection failure
     */
    public SimulationPose2d simulationPose2d(int index, String model) throws IOException {
        DeviceAddress dev = deviceAddress(Interfaces.SIMULATION, index);
        int at = connection.begin(dev, MessageType.REQ, Subtypes.SIMULATION_REQ_GET_POSE2D);
        PlayerCodec.writeSimulationPose2d(writer(), new SimulationPose2d(model, 0, 0, 0));
        return PlayerCodec.readSimulationPose2d(requests.request(dev, Subtypes.SIMULATION_REQ_GET_POSE2D,
                "REQ GET_POSE2D of '" + model + "'", at));
    }

    /**
     * Places a simulation model.
     *
     * @param index simulation index
     * @param pose model name and pose
     * @throws IOException on timeout, refusal or connection failure
     */
    public void setSimulationPose2d(int index, SimulationPose2d pose) throws IOException {
        DeviceAddress dev = deviceAddress(Interfaces.SIMULATION, index);
        int at = connection.begin(dev, MessageType.REQ, Subtypes.SIMULATION_REQ_SET_POSE2D);
        PlayerCodec.writeSimulationPose2d(writer(), pose);
        requests.request(dev, Subtypes.SIMULATION_REQ_SET_POSE2D, "REQ SET_POSE2D of '" + pose.name() + "'", at);
    }

    // ---------------------------------------------------------------- latest data

    /** @return the newest plausible position2d state (owned by this client; valid until the next read) */
    public Odometry odometry() {
        return data.odometry();
    }

    /** @return how many plausible position2d states were kept */
    public long odometryUpdates() {
        return data.odometryUpdates();
    }

    /** @return the newest plausible laser scan (owned by this client) */
    public LaserScan laserScan() {
        return data.laserScan();
    }

    /** @return how many plausible laser scans were kept */
    public long laserUpdates() {
        return data.laserUpdates();
    }

    /** @return the newest plausible ranger ranges as a scan (owned by this client) */
    public LaserScan rangerScan() {
        return data.rangerScan();
    }

    /** @return how many plausible ranger ranges were kept (0 until {@link #rangerConfig} was called) */
    public long rangerUpdates() {
        return data.rangerUpdates();
    }

    /** @return SYNCH messages received */
    public long synchs() {
        return data.synchs();
    }

    /** @return the last protocol error found in a data body and skipped, or null */
    public String lastProtocolError() {
        return data.lastProtocolError();
    }

    /** Closes the connection (the server then unsubscribes everything). Idempotent. */
    @Override
    public void close() throws IOException {
        connection.close();
    }
}
