package io.rtaware.player.client;

import io.rtaware.player.protocol.Banner;
import io.rtaware.player.protocol.DeviceAddress;
import io.rtaware.player.protocol.DeviceRequest;
import io.rtaware.player.protocol.DriverInfo;
import io.rtaware.player.protocol.Geometry;
import io.rtaware.player.protocol.Interfaces;
import io.rtaware.player.protocol.LaserConfig;
import io.rtaware.player.protocol.LaserData;
import io.rtaware.player.protocol.MessageType;
import io.rtaware.player.protocol.PlayerCodec;
import io.rtaware.player.protocol.PlayerFrameReader;
import io.rtaware.player.protocol.PlayerHeader;
import io.rtaware.player.protocol.RangerConfig;
import io.rtaware.player.protocol.RangerData;
import io.rtaware.player.protocol.RangerGeometry;
import io.rtaware.player.protocol.ReplaceRule;
import io.rtaware.player.protocol.SimulationPose2d;
import io.rtaware.player.protocol.Subtypes;
import io.rtaware.player.xdr.PlayerProtocolException;
import io.rtaware.player.xdr.XdrReader;
import io.rtaware.player.xdr.XdrWriter;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.Odometry;
import java.io.BufferedInputStream;
import java.io.Closeable;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * A client of one Player server over TCP. {@link #connect} opens the connection and checks
 * the banner; requests ({@link #deviceList()}, {@link #subscribe}, {@link #laserConfig} ...)
 * block until the matching reply (same interface, index and subtype) or the request timeout;
 * {@link #poll} reads what the server sends. Data that arrives while waiting for a reply is
 * kept like data read by {@link #poll}: the newest position2d state in {@link #odometry()},
 * the newest laser scan in {@link #laserScan()} and the newest ranger ranges, converted with
 * the ranger's configuration (fetched by {@link #rangerConfig}), in {@link #rangerScan()}.
 * Messages of other interfaces or subtypes are skipped and counted; a malformed data body is
 * counted as a protocol error and skipped; a broken stream (bad header, stream ended inside a
 * message) is thrown as {@link PlayerProtocolException}, after which the client must be
 * closed.
 *
 * <p>Not thread-safe: one thread owns a client. Its {@link PlayerCounters} may be read from
 * any thread.
 */
public final class PlayerClient implements Closeable {

    private static final int PLAYER_INDEX = 0;

    private final String host;
    private final int port;
    private final PlayerClientOptions options;
    private final PlayerCounters counters;
    private final Socket socket;
    private final InputStream in;
    private final OutputStream out;
    private final String serverVersion;
    private final PlayerFrameReader frames;
    private final XdrWriter writer = new XdrWriter();
    private final DeviceAddress playerAddress;

    private final Odometry odometry = new Odometry();
    private final LaserData laserData;
    private final LaserScan laserScan;
    private final RangerData rangerData;
    private final LaserScan rangerScan;
    private long odometryUpdates;
    private long laserUpdates;
    private long rangerUpdates;
    private int odometryIndex;
    private int laserIndex;
    private int rangerIndex;
    private RangerConfig rangerConfig;
    private long synchs;
    private String lastProtocolError;

    private PlayerClient(String host, int port, PlayerClientOptions options, PlayerCounters counters, Socket socket,
                         InputStream in, OutputStream out, String serverVersion) {
        this.host = host;
        this.port = port;
        this.options = options;
        this.counters = counters;
        this.socket = socket;
        this.in = in;
        this.out = out;
        this.serverVersion = serverVersion;
        this.frames = new PlayerFrameReader(Banner.SIZE_BYTES, options.maxBodyBytes());
        this.laserData = new LaserData(options.scanCapacity());
        this.laserScan = new LaserScan(options.scanCapacity());
        this.rangerData = new RangerData(options.scanCapacity());
        this.rangerScan = new LaserScan(options.scanCapacity());
        this.playerAddress = DeviceAddress.of(Interfaces.PLAYER, PLAYER_INDEX);
    }

    /**
     * Connects and reads the banner. The server starts in PUSH mode.
     *
     * @param host server host
     * @param port server port
     * @param options timeouts and limits
     * @param counters where to count traffic (shared across reconnections)
     * @return the connected client
     * @throws PlayerConnectionException if the server cannot be reached in time
     * @throws PlayerProtocolException if the peer is not a Player server (the message shows
     *     what it sent)
     * @throws IOException on other I/O failures
     */
    public static PlayerClient connect(String host, int port, PlayerClientOptions options, PlayerCounters counters)
            throws IOException {
        Socket socket = new Socket();
        try {
            socket.setTcpNoDelay(true);
            socket.connect(new InetSocketAddress(host, port), options.connectTimeoutMs());
        } catch (IOException e) {
            socket.close();
            throw new PlayerConnectionException("cannot connect to Player server " + host + ":" + port + " within "
                    + options.connectTimeoutMs() + " ms: " + e.getMessage(), e);
        }
        try {
            InputStream in = new BufferedInputStream(socket.getInputStream(), 65536);
            String version = readBanner(socket, in, host + ":" + port, options.connectTimeoutMs(), counters);
            PlayerClient client = new PlayerClient(host, port, options, counters, socket, in,
                    socket.getOutputStream(), version);
            counters.connects++;
            return client;
        } catch (IOException | RuntimeException e) {
            socket.close();
            throw e;
        }
    }

    private static String readBanner(Socket socket, InputStream in, String server, int timeoutMs,
                                     PlayerCounters counters) throws IOException {
        byte[] banner = new byte[Banner.SIZE_BYTES];
        int n = 0;
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMs);
        try {
            while (n < banner.length) {
                long leftMs = TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime());
                if (leftMs <= 0) {
                    throw new SocketTimeoutException();
                }
                socket.setSoTimeout((int) leftMs);
                int r = in.read(banner, n, banner.length - n);
                if (r < 0) {
                    break;
                }
                n += r;
                counters.bytesReceived += r;
            }
        } catch (SocketTimeoutException e) {
            if (n == 0) {
                throw new PlayerTimeoutException("no banner from " + server + " within " + timeoutMs
                        + " ms: the peer sent nothing (not a Player server?)");
            }
        }
        try {
            return Banner.decode(banner, n);
        } catch (PlayerProtocolException e) {
            counters.protocolErrors++;
            throw new PlayerProtocolException(0, "banner", server + " is not a Player server: received " + n
                    + " bytes " + Banner.printable(banner, n) + " instead of a 32-byte banner starting '"
                    + Banner.PREFIX + "'");
        }
    }

    /** @return the version the server announced, e.g. {@code 3.1.1-dev} */
    public String serverVersion() {
        return serverVersion;
    }

    /** @return {@code host:port} of the server */
    public String server() {
        return host + ":" + port;
    }

    /** @return the counters this client updates */
    public PlayerCounters counters() {
        return counters;
    }

    // ---------------------------------------------------------------- sending

    private static double wallTimeS() {
        return System.currentTimeMillis() / 1000.0;
    }

    private DeviceAddress deviceAddress(int interf, int index) {
        // libplayerc sends host 0 and robot = port for device messages; the server ignores both
        return new DeviceAddress(0, port, interf, index);
    }

    private int begin(DeviceAddress dev, int type, int subtype) {
        writer.reset();
        return PlayerCodec.beginMessage(writer, dev, type, subtype, wallTimeS());
    }

    private void send(int headerAt) throws IOException {
        PlayerCodec.endMessage(writer, headerAt);
        try {
            out.write(writer.array(), 0, writer.size());
            out.flush();
        } catch (IOException e) {
            throw lost("sending to", e);
        }
        counters.messagesSent++;
        counters.bytesSent += writer.size();
    }

    private PlayerConnectionException lost(String what, IOException e) {
        return new PlayerConnectionException("connection to Player server " + server() + " lost while " + what
                + " it: " + e.getMessage(), e);
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
        int at = begin(deviceAddress(Interfaces.POSITION2D, index), MessageType.CMD, Subtypes.POSITION2D_CMD_VEL);
        PlayerCodec.writeVelocityCmd(writer, vxMps, vyMps, omegaRadPerSec, state);
        send(at);
        counters.commandsSent++;
    }

    /**
     * PULL mode: asks for one round of data without waiting; {@link #poll} with
     * {@code untilSynch} then reads the acknowledgement, the data and the closing SYNCH.
     *
     * @throws IOException if the connection fails
     */
    public void requestData() throws IOException {
        send(begin(playerAddress, MessageType.REQ, Subtypes.PLAYER_REQ_DATA));
    }

    // ---------------------------------------------------------------- requests

    private XdrReader request(DeviceAddress dev, int subtype, String what, int headerAt) throws IOException {
        send(headerAt);
        return awaitReply(dev, subtype, what, server() + " refused " + what + " (RESP_NACK from " + dev + ")");
    }

    private XdrReader awaitReply(DeviceAddress dev, int subtype, String what, String nackMessage)
            throws IOException {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(options.requestTimeoutMs());
        while (true) {
            long leftNs = deadline - System.nanoTime();
            PlayerHeader h = leftNs <= 0 ? null : readOne(leftNs);
            if (h == null) {
                throw new PlayerTimeoutException("no reply from " + dev + " to " + what + " within "
                        + options.requestTimeoutMs() + " ms (Player does not answer requests to devices it does"
                        + " not have)");
            }
            boolean reply = h.type() == MessageType.RESP_ACK || h.type() == MessageType.RESP_NACK;
            if (reply && h.interf() == dev.interf() && h.index() == dev.index() && h.subtype() == subtype) {
                if (h.type() == MessageType.RESP_NACK) {
                    throw new PlayerNackException(nackMessage);
                }
                return frames.body();
            }
            dispatch(h);
        }
    }

    /**
     * Reads one message, waiting at most {@code waitNs}.
     *
     * @return the header, or null if nothing complete arrived in time
     */
    private PlayerHeader readOne(long waitNs) throws IOException {
        long before = frames.bytesRead();
        try {
            socket.setSoTimeout((int) Math.max(1, Math.min(Integer.MAX_VALUE, TimeUnit.NANOSECONDS.toMillis(waitNs))));
            PlayerHeader h = frames.read(in);
            counters.messagesReceived++;
            return h;
        } catch (SocketTimeoutException e) {
            return null;
        } catch (EOFException e) {
            throw new PlayerConnectionException("Player server " + server() + " closed the connection", e);
        } catch (PlayerProtocolException e) {
            counters.protocolErrors++;
            throw e;
        } catch (IOException e) {
            throw lost("reading from", e);
        } finally {
            counters.bytesReceived += frames.bytesRead() - before;
        }
    }

    /** Handles a message that is not the awaited reply. */
    private void dispatch(PlayerHeader h) {
        XdrReader body = frames.body();
        try {
            switch (h.type()) {
                case MessageType.DATA -> dispatchData(h, body);
                case MessageType.SYNCH -> {
                    synchs++;
                    counters.synchs++;
                }
                case MessageType.RESP_ACK -> {
                    if (!(h.interf() == Interfaces.PLAYER && h.subtype() == Subtypes.PLAYER_REQ_DATA)) {
                        counters.skippedMessages++;
                    }
                }
                default -> counters.skippedMessages++;
            }
        } catch (PlayerProtocolException e) {
            counters.protocolErrors++;
            lastProtocolError = e.getMessage();
        }
    }

    private void dispatchData(PlayerHeader h, XdrReader body) throws PlayerProtocolException {
        if (h.interf() == Interfaces.POSITION2D && h.subtype() == Subtypes.POSITION2D_DATA_STATE
                && h.index() == odometryIndex) {
            PlayerCodec.readPosition2dState(body, odometry);
            odometry.serverTimeS = h.timestampS();
            odometryUpdates++;
            counters.odometryMessages++;
        } else if (h.interf() == Interfaces.LASER && h.subtype() == Subtypes.LASER_DATA_SCAN
                && h.index() == laserIndex) {
            PlayerCodec.readLaserScan(body, laserData);
            laserData.toLaserScan(laserScan, h.timestampS());
            laserUpdates++;
            counters.scanMessages++;
        } else if (h.interf() == Interfaces.RANGER && h.subtype() == Subtypes.RANGER_DATA_RANGE
                && h.index() == rangerIndex && rangerConfig != null) {
            PlayerCodec.readRangerData(body, rangerData);
            rangerData.toLaserScan(rangerScan, rangerConfig, h.timestampS());
            rangerUpdates++;
            counters.scanMessages++;
        } else {
            counters.skippedMessages++;
        }
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
        long synchsBefore = synchs;
        int n = 0;
        while (true) {
            long leftNs = deadline - System.nanoTime();
            if (leftNs <= 0) {
                return n;
            }
            PlayerHeader h = readOne(leftNs);
            if (h == null) {
                return n;
            }
            n++;
            dispatch(h);
            if (untilSynch ? synchs != synchsBefore : available() == 0) {
                return n;
            }
        }
    }

    private int available() throws IOException {
        try {
            return in.available();
        } catch (IOException e) {
            throw lost("reading from", e);
        }
    }

    /**
     * Switches between PUSH and PULL.
     *
     * @param mode {@link Subtypes#DATAMODE_PUSH} or {@link Subtypes#DATAMODE_PULL}
     * @throws IOException on timeout, refusal or connection failure
     */
    public void setDataMode(int mode) throws IOException {
        int at = begin(playerAddress, MessageType.REQ, Subtypes.PLAYER_REQ_DATAMODE);
        PlayerCodec.writeDataMode(writer, mode);
        request(playerAddress, Subtypes.PLAYER_REQ_DATAMODE, "REQ DATAMODE", at);
    }

    /**
     * Adds a replace rule to this connection's queue on the server.
     *
     * @param rule the rule, e.g. {@link ReplaceRule#latestDataOnly()}
     * @throws IOException on timeout, refusal or connection failure
     */
    public void addReplaceRule(ReplaceRule rule) throws IOException {
        int at = begin(playerAddress, MessageType.REQ, Subtypes.PLAYER_REQ_ADD_REPLACE_RULE);
        PlayerCodec.writeReplaceRule(writer, rule);
        request(playerAddress, Subtypes.PLAYER_REQ_ADD_REPLACE_RULE, "REQ ADD_REPLACE_RULE", at);
    }

    /**
     * @return the server's devices
     * @throws IOException on timeout, refusal, malformed reply or connection failure
     */
    public List<DeviceAddress> deviceList() throws IOException {
        int at = begin(playerAddress, MessageType.REQ, Subtypes.PLAYER_REQ_DEVLIST);
        return PlayerCodec.readDeviceList(request(playerAddress, Subtypes.PLAYER_REQ_DEVLIST, "REQ DEVLIST", at));
    }

    /**
     * @param device a device of the server
     * @return its driver's name
     * @throws IOException on timeout, refusal, malformed reply or connection failure
     */
    public String driverInfo(DeviceAddress device) throws IOException {
        int at = begin(playerAddress, MessageType.REQ, Subtypes.PLAYER_REQ_DRIVERINFO);
        PlayerCodec.writeDriverInfo(writer, new DriverInfo(device, ""));
        return PlayerCodec.readDriverInfo(request(playerAddress, Subtypes.PLAYER_REQ_DRIVERINFO,
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
        switch (device.interf()) {
            case Interfaces.POSITION2D -> odometryIndex = device.index();
            case Interfaces.LASER -> laserIndex = device.index();
            case Interfaces.RANGER -> rangerIndex = device.index();
            default -> {
                // other interfaces: subscribed, their data is counted as skipped
            }
        }
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
        int at = begin(playerAddress, MessageType.REQ, Subtypes.PLAYER_REQ_DEV);
        PlayerCodec.writeDeviceRequest(writer, new DeviceRequest(DeviceAddress.of(device.interf(), device.index()),
                access, ""));
        send(at);
        DeviceRequest reply = PlayerCodec.readDeviceRequest(awaitReply(playerAddress, Subtypes.PLAYER_REQ_DEV, what,
                server() + " has no device " + device + " (RESP_NACK to " + what + ")"));
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
        int at = begin(dev, MessageType.REQ, Subtypes.POSITION2D_REQ_GET_GEOM);
        return PlayerCodec.readGeometry(request(dev, Subtypes.POSITION2D_REQ_GET_GEOM, "REQ GET_GEOM", at));
    }

    /**
     * @param index position2d index
     * @param on true to enable the motors
     * @throws IOException on timeout, refusal or connection failure
     */
    public void setMotorPower(int index, boolean on) throws IOException {
        DeviceAddress dev = deviceAddress(Interfaces.POSITION2D, index);
        int at = begin(dev, MessageType.REQ, Subtypes.POSITION2D_REQ_MOTOR_POWER);
        PlayerCodec.writeMotorPower(writer, on);
        request(dev, Subtypes.POSITION2D_REQ_MOTOR_POWER, "REQ MOTOR_POWER", at);
    }

    /**
     * @param index laser index
     * @return the laser's pose on the robot and size
     * @throws IOException on timeout, refusal, malformed reply or connection failure
     */
    public Geometry laserGeometry(int index) throws IOException {
        DeviceAddress dev = deviceAddress(Interfaces.LASER, index);
        int at = begin(dev, MessageType.REQ, Subtypes.LASER_REQ_GET_GEOM);
        return PlayerCodec.readGeometry(request(dev, Subtypes.LASER_REQ_GET_GEOM, "REQ GET_GEOM", at));
    }

    /**
     * @param index laser index
     * @return the scan configuration
     * @throws IOException on timeout, refusal, malformed reply or connection failure
     */
    public LaserConfig laserConfig(int index) throws IOException {
        DeviceAddress dev = deviceAddress(Interfaces.LASER, index);
        int at = begin(dev, MessageType.REQ, Subtypes.LASER_REQ_GET_CONFIG);
        return PlayerCodec.readLaserConfig(request(dev, Subtypes.LASER_REQ_GET_CONFIG, "REQ GET_CONFIG", at));
    }

    /**
     * @param index ranger index
     * @return the ranger's geometry
     * @throws IOException on timeout, refusal, malformed reply or connection failure
     */
    public RangerGeometry rangerGeometry(int index) throws IOException {
        DeviceAddress dev = deviceAddress(Interfaces.RANGER, index);
        int at = begin(dev, MessageType.REQ, Subtypes.RANGER_REQ_GET_GEOM);
        return PlayerCodec.readRangerGeometry(request(dev, Subtypes.RANGER_REQ_GET_GEOM, "REQ GET_GEOM", at));
    }

    /**
     * Fetches the ranger's configuration and keeps it: ranger ranges are converted into
     * {@link #rangerScan()} with its angles and maximum range from then on.
     *
     * @param index ranger index
     * @return the configuration
     * @throws IOException on timeout, refusal, malformed reply or connection failure
     */
    public RangerConfig rangerConfig(int index) throws IOException {
        DeviceAddress dev = deviceAddress(Interfaces.RANGER, index);
        int at = begin(dev, MessageType.REQ, Subtypes.RANGER_REQ_GET_CONFIG);
        RangerConfig c = PlayerCodec.readRangerConfig(request(dev, Subtypes.RANGER_REQ_GET_CONFIG,
                "REQ GET_CONFIG", at));
        if (index == rangerIndex) {
            rangerConfig = c;
        }
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
        int at = begin(dev, MessageType.REQ, Subtypes.SIMULATION_REQ_GET_POSE2D);
        PlayerCodec.writeSimulationPose2d(writer, new SimulationPose2d(model, 0, 0, 0));
        return PlayerCodec.readSimulationPose2d(request(dev, Subtypes.SIMULATION_REQ_GET_POSE2D,
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
        int at = begin(dev, MessageType.REQ, Subtypes.SIMULATION_REQ_SET_POSE2D);
        PlayerCodec.writeSimulationPose2d(writer, pose);
        request(dev, Subtypes.SIMULATION_REQ_SET_POSE2D, "REQ SET_POSE2D of '" + pose.name() + "'", at);
    }

    // ---------------------------------------------------------------- latest data

    /** @return the newest position2d state (owned by this client; valid until the next read) */
    public Odometry odometry() {
        return odometry;
    }

    /** @return how many position2d states were received */
    public long odometryUpdates() {
        return odometryUpdates;
    }

    /** @return the newest laser scan (owned by this client) */
    public LaserScan laserScan() {
        return laserScan;
    }

    /** @return how many laser scans were received */
    public long laserUpdates() {
        return laserUpdates;
    }

    /** @return the newest ranger ranges as a scan (owned by this client) */
    public LaserScan rangerScan() {
        return rangerScan;
    }

    /** @return how many ranger ranges were converted (0 until {@link #rangerConfig} was called) */
    public long rangerUpdates() {
        return rangerUpdates;
    }

    /** @return SYNCH messages received */
    public long synchs() {
        return synchs;
    }

    /** @return the last protocol error found in a data body and skipped, or null */
    public String lastProtocolError() {
        return lastProtocolError;
    }

    /** Closes the connection (the server then unsubscribes everything). Idempotent. */
    @Override
    public void close() throws IOException {
        socket.close();
    }
}
