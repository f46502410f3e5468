package io.rtaware.sim.server;

import io.rtaware.core.time.Clock;
import io.rtaware.player.protocol.Banner;
import io.rtaware.player.protocol.Bbox3d;
import io.rtaware.player.protocol.DeviceAddress;
import io.rtaware.player.protocol.DeviceRequest;
import io.rtaware.player.protocol.DriverInfo;
import io.rtaware.player.protocol.Geometry;
import io.rtaware.player.protocol.Interfaces;
import io.rtaware.player.protocol.LaserConfig;
import io.rtaware.player.protocol.LaserData;
import io.rtaware.player.protocol.MessageType;
import io.rtaware.player.protocol.PlayerCodec;
import io.rtaware.player.protocol.PlayerHeader;
import io.rtaware.player.protocol.Pose3d;
import io.rtaware.player.protocol.RangerConfig;
import io.rtaware.player.protocol.RangerData;
import io.rtaware.player.protocol.RangerGeometry;
import io.rtaware.player.protocol.ReplaceRule;
import io.rtaware.player.protocol.SimulationPose2d;
import io.rtaware.player.protocol.Subtypes;
import io.rtaware.player.protocol.VelocityCmd;
import io.rtaware.player.xdr.PlayerProtocolException;
import io.rtaware.player.xdr.XdrReader;
import io.rtaware.player.xdr.XdrWriter;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.sim.world.World;
import java.io.IOException;
import java.lang.System.Logger.Level;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketException;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.locks.LockSupport;
import java.util.function.Function;

/**
 * Serves a {@link World} over the Player 3.1 TCP protocol, so a controller cannot tell it from
 * a Player/Stage server: 32-byte banner, {@code player:0} (DEVLIST, DRIVERINFO, DEV, DATA,
 * DATAMODE PUSH/PULL, ADD_REPLACE_RULE), {@code position2d:0} (DATA STATE at the odometry rate,
 * CMD VEL, GET_GEOM, MOTOR_POWER), {@code laser:0} (DATA SCAN at the laser rate, GET_GEOM,
 * GET_CONFIG), {@code ranger:0} (DATA RANGE and INTNS, GET_GEOM, GET_CONFIG) and
 * {@code simulation:0} (GET_POSE2D/SET_POSE2D of the model named in {@link ServerConfig}).
 * Timestamps are simulation time in seconds.
 *
 * <p>Two ways to run the world: {@link #start(World, Clock, ServerConfig)} starts a sim thread
 * that steps the world by the world time the clock shows (aiming at
 * {@link ServerConfig#stepPeriodNs()} steps, waiting via {@link Clock#toWallNanos(long)}, so
 * with a scaled clock the world runs K times faster); {@link #startManual(World, ServerConfig)}
 * starts no thread, and the caller steps with {@link #step(long)}.
 *
 * <p>Each client gets a reader and a writer thread; data is queued per client (bounded, replace
 * rules honoured, oldest dropped when full), so a slow client never blocks the world. A client
 * sending malformed messages is disconnected with one log line. Divergences from Player: a
 * request to a device the server lacks gets a RESP_NACK (Player drops it silently); the laser
 * publishes one scan per sensor update (Player's rangertolaser publishes two); when the queue
 * is full the oldest data is dropped (Player drops the newest).
 *
 * <p>Thread-safe. The world is guarded by an internal lock; do not use it directly while the
 * server runs, use {@link #withWorld(Function)}.
 */
public final class PlayerSimServer implements AutoCloseable {

    private static final System.Logger LOG = System.getLogger(PlayerSimServer.class.getName());

    /** The version the banner announces. */
    public static final String VERSION = "3.1.1-rtaware-sim";
    /** Driver name reported for simulation, position2d and ranger (as Stage's plugin does). */
    public static final String STAGE_DRIVER = "stage";
    /** Driver name reported for laser (as Player's converter on top of Stage's ranger). */
    public static final String LASER_DRIVER = "rangertolaser";
    /** Most fixed steps the sim thread takes to catch up; a larger backlog is taken in one long step. */
    private static final long MAX_BACKLOG_STEPS = 1000;

    /** The laser's mounting (robot centre) and size (URG-04LX: 50 x 50 x 70 mm). */
    private static final Geometry LASER_GEOMETRY =
            new Geometry(new Pose3d(0, 0, 0, 0, 0, 0), new Bbox3d(0.05, 0.05, 0.07));

    private static final int SIM = key(Interfaces.SIMULATION, 0);
    private static final int POSITION = key(Interfaces.POSITION2D, 0);
    private static final int RANGER = key(Interfaces.RANGER, 0);
    private static final int LASER = key(Interfaces.LASER, 0);

    private final World world;
    private final ServerConfig config;
    private final Object worldLock = new Object();
    private final ServerSocket serverSocket;
    private final long host;
    private final long robot;
    private final List<DeviceAddress> devices;
    private final byte[] banner = Banner.encode(VERSION);
    private final byte[] synchOk;
    private final CopyOnWriteArrayList<ClientSession> sessions = new CopyOnWriteArrayList<>();
    private final Thread acceptThread;
    private final Thread simThread;
    private final LaserData laserData;
    private final RangerData rangerData;
    private final byte[] intensities;
    private volatile double simTimeS;
    private volatile boolean running = true;

    private PlayerSimServer(World world, Clock clock, ServerConfig config) throws IOException {
        this.world = Objects.requireNonNull(world, "world");
        this.config = Objects.requireNonNull(config, "config");
        InetAddress bind = InetAddress.getByName(config.bindAddress());
        this.serverSocket = new ServerSocket();
        serverSocket.setReuseAddress(true);
        serverSocket.bind(new InetSocketAddress(bind, config.port()), 50);
        byte[] ip = bind.getAddress();
        if (ip.length != 4 || bind.isAnyLocalAddress()) {
            ip = new byte[] {127, 0, 0, 1};
        }
        // Player puts the raw network-order IPv4 address into a host-order uint32 (x86).
        this.host = (ip[0] & 0xffL) | (ip[1] & 0xffL) << 8 | (ip[2] & 0xffL) << 16 | (ip[3] & 0xffL) << 24;
        this.robot = serverSocket.getLocalPort();
        this.devices = List.of(addr(Interfaces.SIMULATION), addr(Interfaces.POSITION2D), addr(Interfaces.RANGER),
                addr(Interfaces.LASER));
        XdrWriter w = new XdrWriter(64);
        int at = PlayerCodec.beginMessage(w, DeviceAddress.of(Interfaces.PLAYER, 0), MessageType.SYNCH,
                Subtypes.PLAYER_SYNCH_OK, 0.0);
        PlayerCodec.endMessage(w, at);
        this.synchOk = w.toByteArray();
        int beams = world.laserConfig().beams();
        this.laserData = new LaserData(beams);
        this.rangerData = new RangerData(beams);
        this.intensities = new byte[beams];
        this.simTimeS = world.timeS();
        this.acceptThread = new Thread(this::acceptLoop, "rtaware-sim-accept :" + robot);
        acceptThread.setDaemon(true);
        if (clock != null) {
            this.simThread = new Thread(() -> simLoop(clock), "rtaware-sim-world :" + robot);
            simThread.setDaemon(true);
        } else {
            this.simThread = null;
        }
    }

    /**
     * Starts serving and a sim thread that steps the world on {@code clock}.
     *
     * @param world the world (owned by the server from now on)
     * @param clock world time; with a scaled clock the world runs that much faster
     * @param config address, port, model name and queue limits
     * @return the running server
     * @throws IOException if the port cannot be bound
     */
    public static PlayerSimServer start(World world, Clock clock, ServerConfig config) throws IOException {
        PlayerSimServer s = new PlayerSimServer(world, Objects.requireNonNull(clock, "clock"), config);
        s.acceptThread.start();
        s.simThread.start();
        LOG.log(Level.INFO, "rtaware-sim: serving Player on " + config.bindAddress() + ":" + s.port()
                + " (" + clock + ")");
        return s;
    }

    /**
     * Starts serving without a sim thread: the caller advances the world with {@link #step(long)}.
     *
     * @param world the world (owned by the server from now on)
     * @param config address, port, model name and queue limits
     * @return the running server
     * @throws IOException if the port cannot be bound
     */
    public static PlayerSimServer startManual(World world, ServerConfig config) throws IOException {
        PlayerSimServer s = new PlayerSimServer(world, null, config);
        s.acceptThread.start();
        return s;
    }

    /** @return the TCP port actually bound (useful with port 0) */
    public int port() {
        return serverSocket.getLocalPort();
    }

    /** @return the configuration */
    public ServerConfig config() {
        return config;
    }

    /** @return the number of connected clients */
    public int clientCount() {
        return sessions.size();
    }

    /** @return simulation time in seconds (the timestamps the server sends) */
    public double simTimeS() {
        return simTimeS;
    }

    /** @return the robot's ground-truth pose */
    public Pose2d groundTruth() {
        synchronized (worldLock) {
            return world.pose();
        }
    }

    /**
     * Runs a function on the world under the server's lock (e.g. to read the contact count).
     *
     * @param f what to do; must not keep the world
     * @param <T> the result type
     * @return f's result
     */
    public <T> T withWorld(Function<World, T> f) {
        synchronized (worldLock) {
            return f.apply(world);
        }
    }

    /**
     * Advances the world by {@code dtNs} and sends what it published to subscribed clients.
     * Only for servers started with {@link #startManual(World, ServerConfig)}.
     *
     * @param dtNs world nanoseconds, not negative
     * @throws IllegalStateException if a sim thread steps this server
     */
    public void step(long dtNs) {
        if (simThread != null) {
            throw new IllegalStateException("the sim thread steps this server; step() is for startManual servers");
        }
        stepAndPublish(dtNs);
    }

    private void simLoop(Clock clock) {
        long stepNs = config.stepPeriodNs();
        long last = clock.nanos();
        while (running) {
            long target = last + stepNs;
            long now = clock.nanos();
            while (running && now < target) {
                LockSupport.parkNanos(Math.max(1_000L, clock.toWallNanos(target - now)));
                now = clock.nanos();
            }
            if (!running) {
                return;
            }
            long behind = now - last;
            long maxBacklogNs = MAX_BACKLOG_STEPS * stepNs;
            if (behind > maxBacklogNs) {
                // cannot keep up (or the clock jumped): take the excess in one long step
                stepAndPublish(behind - maxBacklogNs);
                behind = maxBacklogNs;
            }
            while (behind >= stepNs) {
                stepAndPublish(stepNs);
                behind -= stepNs;
            }
            last = now - behind;
        }
    }

    private void stepAndPublish(long dtNs) {
        List<ClientSession.Outgoing> batch = new ArrayList<>(4);
        int[] keys = new int[4];
        synchronized (worldLock) {
            world.step(dtNs);
            double t = world.timeS();
            simTimeS = t;
            if (world.odometryFresh() && anySubscribed(POSITION)) {
                XdrWriter w = new XdrWriter(128);
                int at = PlayerCodec.beginMessage(w, addr(Interfaces.POSITION2D), MessageType.DATA,
                        Subtypes.POSITION2D_DATA_STATE, t);
                PlayerCodec.writePosition2dState(w, world.odometry());
                PlayerCodec.endMessage(w, at);
                keys[batch.size()] = POSITION;
                batch.add(data(w, Interfaces.POSITION2D, Subtypes.POSITION2D_DATA_STATE));
            }
            boolean ranger = world.scanFresh() && anySubscribed(RANGER);
            boolean laser = world.scanFresh() && anySubscribed(LASER);
            LaserScan scan = world.scan();
            int n = scan.count();
            if (ranger || laser) {
                for (int i = 0; i < n; i++) {
                    intensities[i] = (byte) (scan.rangesM[i] < scan.maxRangeM ? 1 : 0);
                }
            }
            if (ranger) {
                rangerData.count = n;
                for (int i = 0; i < n; i++) {
                    rangerData.values[i] = scan.rangesM[i];
                }
                XdrWriter w = new XdrWriter(16 * n + 128);
                int at = PlayerCodec.beginMessage(w, addr(Interfaces.RANGER), MessageType.DATA,
                        Subtypes.RANGER_DATA_RANGE, t);
                PlayerCodec.writeRangerData(w, rangerData);
                PlayerCodec.endMessage(w, at);
                keys[batch.size()] = RANGER;
                batch.add(data(w, Interfaces.RANGER, Subtypes.RANGER_DATA_RANGE));
                for (int i = 0; i < n; i++) {
                    rangerData.values[i] = intensities[i];
                }
                w = new XdrWriter(8 * n + 128);
                at = PlayerCodec.beginMessage(w, addr(Interfaces.RANGER), MessageType.DATA,
                        Subtypes.RANGER_DATA_INTNS, t);
                PlayerCodec.writeRangerData(w, rangerData);
                PlayerCodec.endMessage(w, at);
                keys[batch.size()] = RANGER;
                batch.add(data(w, Interfaces.RANGER, Subtypes.RANGER_DATA_INTNS));
            }
            if (laser) {
                fillLaserData(scan);
                XdrWriter w = new XdrWriter(5 * n + 128);
                int at = PlayerCodec.beginMessage(w, addr(Interfaces.LASER), MessageType.DATA,
                        Subtypes.LASER_DATA_SCAN, t);
                PlayerCodec.writeLaserScan(w, laserData);
                PlayerCodec.endMessage(w, at);
                keys[batch.size()] = LASER;
                batch.add(data(w, Interfaces.LASER, Subtypes.LASER_DATA_SCAN));
            }
        }
        if (batch.isEmpty()) {
            return;
        }
        for (ClientSession s : sessions) {
            s.deliver(batch, keys);
        }
    }

    private boolean anySubscribed(int deviceKey) {
        for (ClientSession s : sessions) {
            if (s.subscribed(deviceKey)) {
                return true;
            }
        }
        return false;
    }

    private void fillLaserData(LaserScan scan) {
        int n = scan.count();
        laserData.minAngleRad = (float) scan.minAngleRad;
        laserData.maxAngleRad = (float) scan.maxAngleRad;
        laserData.resolutionRad = (float) world.laserConfig().angleIncrementRad();
        laserData.maxRangeM = (float) scan.maxRangeM;
        System.arraycopy(scan.rangesM, 0, laserData.rangesM, 0, n);
        laserData.rangeCount = n;
        System.arraycopy(intensities, 0, laserData.intensities, 0, n);
        laserData.intensityCount = n;
        laserData.id = 0;
    }

    private static ClientSession.Outgoing data(XdrWriter w, int interf, int subtype) {
        return new ClientSession.Outgoing(w.toByteArray(), interf, 0, MessageType.DATA, subtype);
    }

    private void acceptLoop() {
        while (running) {
            Socket socket;
            try {
                socket = serverSocket.accept();
            } catch (IOException e) {
                if (running) {
                    LOG.log(Level.WARNING, "rtaware-sim: accept failed: " + e.getMessage());
                }
                continue;
            }
            try {
                socket.setTcpNoDelay(true);
            } catch (SocketException e) {
                LOG.log(Level.DEBUG, "rtaware-sim: TCP_NODELAY: " + e.getMessage());
            }
            ClientSession[] holder = new ClientSession[1];
            ClientSession session = new ClientSession(socket, config.queueLimit(), config.maxRequestBytes(), banner,
                    synchOk, this::handle, () -> sessions.remove(holder[0]));
            holder[0] = session;
            sessions.add(session);
            if (!running) {
                session.close();
                return;
            }
            session.start();
            LOG.log(Level.DEBUG, "rtaware-sim: client " + session.name() + " connected");
        }
    }

    // ------------------------------------------------------------------ requests

    private void handle(ClientSession s, PlayerHeader h, XdrReader body) throws IOException {
        if (h.type() != MessageType.REQ && h.type() != MessageType.CMD) {
            throw new PlayerProtocolException(0, "header.type", "a client may send only REQ (3) or CMD (2), got "
                    + h.type() + " (" + MessageType.name(h.type()) + ")");
        }
        int key = key(h.interf(), h.index());
        if (h.type() == MessageType.CMD) {
            if (key == POSITION && h.subtype() == Subtypes.POSITION2D_CMD_VEL) {
                VelocityCmd c = PlayerCodec.readVelocityCmd(body);
                synchronized (worldLock) {
                    world.command(c.vxMps(), c.omegaRadPerSec());
                }
            }
            // other commands (and commands to devices we lack) are ignored, as Player does
            return;
        }
        if (h.interf() == Interfaces.PLAYER && h.index() == 0) {
            handlePlayer(s, h, body);
        } else if (key == POSITION) {
            handlePosition(s, h, body);
        } else if (key == LASER) {
            handleLaser(s, h);
        } else if (key == RANGER) {
            handleRanger(s, h);
        } else if (key == SIM) {
            handleSimulation(s, h, body);
        } else {
            nack(s, h);
        }
    }

    private void handlePlayer(ClientSession s, PlayerHeader h, XdrReader body) throws PlayerProtocolException {
        switch (h.subtype()) {
            case Subtypes.PLAYER_REQ_DEVLIST -> s.reply(message(h, MessageType.RESP_ACK,
                    w -> PlayerCodec.writeDeviceList(w, devices)));
            case Subtypes.PLAYER_REQ_DRIVERINFO -> {
                DriverInfo info = PlayerCodec.readDriverInfo(body);
                String driver = driverOf(info.device());
                if (driver == null) {
                    nack(s, h);
                } else {
                    s.reply(message(h, MessageType.RESP_ACK, w -> PlayerCodec.writeDriverInfo(w,
                            new DriverInfo(addr(info.device().interf()), driver))));
                }
            }
            case Subtypes.PLAYER_REQ_DEV -> {
                DeviceRequest req = PlayerCodec.readDeviceRequest(body);
                String driver = driverOf(req.device());
                DeviceAddress a = new DeviceAddress(host, robot, req.device().interf(), req.device().index());
                if (driver == null || (req.access() != Subtypes.ACCESS_OPEN && req.access() != Subtypes.ACCESS_CLOSE)) {
                    s.reply(message(h, MessageType.RESP_NACK, w -> PlayerCodec.writeDeviceRequest(w,
                            new DeviceRequest(a, Subtypes.ACCESS_ERROR, ""))));
                } else {
                    int key = key(a.interf(), a.index());
                    if (req.access() == Subtypes.ACCESS_OPEN) {
                        s.subscribe(key);
                    } else {
                        s.unsubscribe(key);
                    }
                    s.reply(message(h, MessageType.RESP_ACK, w -> PlayerCodec.writeDeviceRequest(w,
                            new DeviceRequest(a, req.access(), driver))));
                }
            }
            case Subtypes.PLAYER_REQ_DATA -> s.pullRound(message(h, MessageType.RESP_ACK, w -> { }));
            case Subtypes.PLAYER_REQ_DATAMODE -> {
                int mode = PlayerCodec.readDataMode(body);
                if (mode == Subtypes.DATAMODE_PUSH || mode == Subtypes.DATAMODE_PULL) {
                    s.setPull(mode == Subtypes.DATAMODE_PULL);
                    s.reply(message(h, MessageType.RESP_ACK, w -> { }));
                } else {
                    nack(s, h);
                }
            }
            case Subtypes.PLAYER_REQ_ADD_REPLACE_RULE -> {
                ReplaceRule rule = PlayerCodec.readReplaceRule(body);
                if (rule.replace() < Subtypes.REPLACE_ACCEPT || rule.replace() > Subtypes.REPLACE_IGNORE) {
                    nack(s, h);
                } else {
                    s.addRule(rule);
                    s.reply(message(h, MessageType.RESP_ACK, w -> { }));
                }
            }
            default -> nack(s, h);
        }
    }

    private void handlePosition(ClientSession s, PlayerHeader h, XdrReader body) throws PlayerProtocolException {
        switch (h.subtype()) {
            case Subtypes.POSITION2D_REQ_GET_GEOM -> {
                double d = 2 * world.robotConfig().radiusM();
                s.reply(message(h, MessageType.RESP_ACK, w -> PlayerCodec.writeGeometry(w,
                        new Geometry(new Pose3d(0, 0, 0, 0, 0, 0), new Bbox3d(d, d, 0)))));
            }
            case Subtypes.POSITION2D_REQ_MOTOR_POWER -> {
                boolean on = PlayerCodec.readMotorPower(body);
                synchronized (worldLock) {
                    world.setMotorsEnabled(on);
                }
                s.reply(message(h, MessageType.RESP_ACK, w -> { }));
            }
            default -> nack(s, h);
        }
    }

    private void handleLaser(ClientSession s, PlayerHeader h) {
        io.rtaware.sim.world.LaserConfig c = world.laserConfig();
        switch (h.subtype()) {
            case Subtypes.LASER_REQ_GET_GEOM -> s.reply(message(h, MessageType.RESP_ACK,
                    w -> PlayerCodec.writeGeometry(w, LASER_GEOMETRY)));
            case Subtypes.LASER_REQ_GET_CONFIG -> s.reply(message(h, MessageType.RESP_ACK,
                    w -> PlayerCodec.writeLaserConfig(w, new LaserConfig((float) c.minAngleRad(),
                            (float) c.maxAngleRad(), (float) c.angleIncrementRad(), (float) c.maxRangeM(),
                            0.001f, 1, (float) c.rateHz()))));
            default -> nack(s, h);
        }
    }

    private void handleRanger(ClientSession s, PlayerHeader h) {
        io.rtaware.sim.world.LaserConfig c = world.laserConfig();
        switch (h.subtype()) {
            case Subtypes.RANGER_REQ_GET_GEOM -> s.reply(message(h, MessageType.RESP_ACK,
                    w -> PlayerCodec.writeRangerGeometry(w, new RangerGeometry(LASER_GEOMETRY.pose(),
                            LASER_GEOMETRY.size(), List.of(LASER_GEOMETRY.pose()), List.of(LASER_GEOMETRY.size())))));
            case Subtypes.RANGER_REQ_GET_CONFIG -> s.reply(message(h, MessageType.RESP_ACK,
                    w -> PlayerCodec.writeRangerConfig(w, new RangerConfig(c.minAngleRad(), c.maxAngleRad(),
                            c.angleIncrementRad(), c.minRangeM(), c.maxRangeM(), 0.001, c.rateHz()))));
            default -> nack(s, h);
        }
    }

    private void handleSimulation(ClientSession s, PlayerHeader h, XdrReader body) throws PlayerProtocolException {
        if (h.subtype() != Subtypes.SIMULATION_REQ_GET_POSE2D && h.subtype() != Subtypes.SIMULATION_REQ_SET_POSE2D) {
            nack(s, h);
            return;
        }
        SimulationPose2d req = PlayerCodec.readSimulationPose2d(body);
        if (!config.modelName().equals(req.name())) {
            nack(s, h);
            return;
        }
        if (h.subtype() == Subtypes.SIMULATION_REQ_SET_POSE2D) {
            if (!Double.isFinite(req.xM()) || !Double.isFinite(req.yM()) || !Double.isFinite(req.yawRad())) {
                nack(s, h);
                return;
            }
            synchronized (worldLock) {
                world.setPose(new Pose2d(req.xM(), req.yM(), req.yawRad()));
            }
            s.reply(message(h, MessageType.RESP_ACK, w -> { }));
        } else {
            Pose2d p = groundTruth();
            s.reply(message(h, MessageType.RESP_ACK, w -> PlayerCodec.writeSimulationPose2d(w,
                    new SimulationPose2d(req.name(), p.xM(), p.yM(), p.yawRad()))));
        }
    }

    private void nack(ClientSession s, PlayerHeader h) {
        s.reply(message(h, MessageType.RESP_NACK, w -> { }));
    }

    private interface Body {
        void write(XdrWriter w);
    }

    /** A reply: the request's address with the server's host and robot, the new type, sim time. */
    private byte[] message(PlayerHeader request, int type, Body body) {
        XdrWriter w = new XdrWriter(256);
        int at = PlayerCodec.beginMessage(w, new DeviceAddress(host, robot, request.interf(), request.index()), type,
                request.subtype(), simTimeS);
        body.write(w);
        PlayerCodec.endMessage(w, at);
        return w.toByteArray();
    }

    static byte[] synchOverflow(long dropped) {
        XdrWriter w = new XdrWriter(64);
        int at = PlayerCodec.beginMessage(w, DeviceAddress.of(Interfaces.PLAYER, 0), MessageType.SYNCH,
                Subtypes.PLAYER_SYNCH_OVERFLOW, 0.0);
        PlayerCodec.writeSynchOverflow(w, dropped);
        PlayerCodec.endMessage(w, at);
        return w.toByteArray();
    }

    private String driverOf(DeviceAddress a) {
        int key = key(a.interf(), a.index());
        if (key == LASER) {
            return LASER_DRIVER;
        }
        return key == SIM || key == POSITION || key == RANGER ? STAGE_DRIVER : null;
    }

    private DeviceAddress addr(int interf) {
        return new DeviceAddress(host, robot, interf, 0);
    }

    private static int key(int interf, int index) {
        return interf << 16 | index;
    }

    /** Stops the sim thread, disconnects every client and closes the port; idempotent. */
    @Override
    public void close() {
        running = false;
        try {
            serverSocket.close();
        } catch (IOException e) {
            LOG.log(Level.DEBUG, "rtaware-sim: closing the server socket: " + e.getMessage());
        }
        for (ClientSession s : sessions) {
            s.close();
        }
        try {
            acceptThread.join(2000);
            if (simThread != null) {
                simThread.join(2000);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
