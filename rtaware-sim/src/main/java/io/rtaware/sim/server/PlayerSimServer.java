package io.rtaware.sim.server;

import io.rtaware.core.agent.AgentThread;
import io.rtaware.core.monitor.WorldClockIdleStrategy;
import io.rtaware.core.time.Clock;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.sim.world.World;
import java.io.IOException;
import java.lang.System.Logger.Level;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.TimeUnit;
import java.util.function.Function;
import org.agrona.concurrent.Agent;
import org.agrona.concurrent.AgentTerminationException;
import org.agrona.concurrent.NoOpIdleStrategy;

/**
 * Serves a {@link World} over the Player 3.1 TCP protocol, so a controller cannot tell it from
 * a Player/Stage server: 32-byte banner, {@code player:0} (DEVLIST, DRIVERINFO, DEV, DATA,
 * DATAMODE PUSH/PULL, ADD_REPLACE_RULE), {@code position2d:0} (DATA STATE at the odometry rate,
 * CMD VEL, GET_GEOM, MOTOR_POWER), {@code laser:0} (DATA SCAN at the laser rate, GET_GEOM,
 * GET_CONFIG), {@code ranger:0} (DATA RANGE and INTNS, GET_GEOM, GET_CONFIG) and
 * {@code simulation:0} (GET_POSE2D/SET_POSE2D of the model named in {@link ServerConfig}).
 * Timestamps are simulation time in seconds.
 *
 * <p>This class wires the parts: {@link ClientAcceptor} (accept loop, client admission),
 * {@link ClientSession} (one client's connection) with its {@link ClientQueue}, {@link RequestRouter}
 * and one {@link DeviceHandler} per device, and {@link WorldStepper} (stepping and publishing).
 *
 * <p>The accept loop ({@code rtaware-sim-accept :PORT}) and the sim thread
 * ({@code rtaware-sim-world :PORT}) are {@link AgentThread}s: an error of the accept loop is
 * logged and the next client served; one of the sim thread is logged and stops the world. The
 * clients' reader and writer threads are not: see {@link ClientSession}.
 *
 * <p>Two ways to run the world: {@link #start(World, Clock, ServerConfig)} starts a sim thread
 * that steps the world by the world time the clock shows (aiming at
 * {@link ServerConfig#stepPeriodNs()} steps, waiting with a {@link WorldClockIdleStrategy}, so
 * with a scaled clock the world runs K times faster and on a manual clock it steps as the clock
 * is advanced); {@link #startManual(World, ServerConfig)}
 * starts no thread, and the caller steps with {@link #step(long)}.
 *
 * <p>Each client gets a reader and a writer thread; data is queued per client (bounded, replace
 * rules honoured, oldest dropped when full), so a slow client never blocks the world. Limits
 * ({@link ServerConfig}): clients at once (more are refused), replace rules per client (more
 * are NACKed), time per message (a client that sends part of a message and stalls is
 * disconnected). A client sending malformed messages is disconnected with one log line. A
 * failing accept is retried with back-off and logged once per episode. Divergences from Player:
 * a request to a device the server lacks gets a RESP_NACK (Player drops it silently); the laser
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
    /** How long {@link #clockOriginNs()} waits for the sim thread's first clock reading. */
    private static final long ORIGIN_WAIT_NS = TimeUnit.SECONDS.toNanos(5);

    private final SharedWorld world;
    private final ServerConfig config;
    private final ServerSocket serverSocket;
    private final ClientAcceptor acceptor;
    private final WorldStepper stepper;
    /** The world's stepping loop, or null for a server stepped by {@link #step(long)}. */
    private final Agent stepping;
    /** How the stepping loop waits for the next step, or null without one. */
    private final WorldClockIdleStrategy steppingIdle;
    private volatile AgentThread acceptThread;
    private volatile AgentThread simThread;

    private PlayerSimServer(World world, Clock clock, ServerConfig config, ServerEnvironment env) throws IOException {
        this.world = new SharedWorld(world);
        this.config = Objects.requireNonNull(config, "config");
        InetAddress bind = InetAddress.getByName(config.bindAddress());
        this.serverSocket = new ServerSocket();
        serverSocket.setReuseAddress(true);
        serverSocket.bind(new InetSocketAddress(bind, config.port()), 50);
        int port = serverSocket.getLocalPort();
        MessageFactory messages = new MessageFactory(hostField(bind), port, VERSION, this.world::timeS);
        List<DeviceHandler> devices = List.of(
                new SimulationDevice(this.world, messages, config.modelName()),
                new Position2dDevice(this.world, messages),
                new RangerDevice(this.world, messages),
                new LaserDevice(this.world, messages));
        List<DeviceHandler> handlers = new ArrayList<>(devices);
        handlers.add(new PlayerDevice(devices, messages));
        ClientSession.Settings session = new ClientSession.Settings(config.queueLimit(), config.maxRequestBytes(),
                config.maxRulesPerClient(), config.messageTimeoutNs(), messages.banner(), messages.synchOk(),
                new RequestRouter(handlers, messages), env.clientThreads(), env.wallClock());
        this.acceptor = new ClientAcceptor(serverSocket, env, config.maxClients(),
                (socket, onClose) -> new ClientSession(socket, session, onClose));
        this.stepper = new WorldStepper(this.world, devices, acceptor.sessions(), config.stepPeriodNs());
        this.steppingIdle = clock == null ? null : new WorldClockIdleStrategy(clock);
        this.stepping = clock == null ? null : stepper.stepping(clock, steppingIdle, "rtaware-sim-world :" + port);
    }

    /** Starts the accept loop and, for a clocked server, the sim thread. */
    private void startThreads() {
        acceptThread = AgentThread.start(acceptor, NoOpIdleStrategy.INSTANCE, error -> LOG.log(Level.WARNING,
                "rtaware-sim: accepting a client failed: " + error + "; serving the next one"));
        if (stepping != null) {
            simThread = AgentThread.start(stepping, steppingIdle, error -> LOG.log(Level.ERROR,
                    "rtaware-sim: the world stopped: a step failed: "
                            + (error instanceof AgentTerminationException && error.getCause() != null ? error.getCause() : error)));
        }
    }

    /** Player puts the raw network-order IPv4 address into a host-order uint32 (x86). */
    private static long hostField(InetAddress bind) {
        byte[] ip = bind.getAddress();
        if (ip.length != 4 || bind.isAnyLocalAddress()) {
            ip = new byte[] {127, 0, 0, 1};
        }
        return (ip[0] & 0xffL) | (ip[1] & 0xffL) << 8 | (ip[2] & 0xffL) << 16 | (ip[3] & 0xffL) << 24;
    }

    /**
     * Starts serving and a sim thread that steps the world on {@code clock}.
     *
     * @param world the world (owned by the server from now on)
     * @param clock world time; with a scaled clock the world runs that much faster
     * @param config address, port, model name and limits
     * @return the running server
     * @throws IOException if the port cannot be bound
     */
    public static PlayerSimServer start(World world, Clock clock, ServerConfig config) throws IOException {
        PlayerSimServer s = new PlayerSimServer(world, Objects.requireNonNull(clock, "clock"), config,
                ServerEnvironment.system());
        s.startThreads();
        LOG.log(Level.INFO, "rtaware-sim: serving Player on " + config.bindAddress() + ":" + s.port()
                + " (" + clock + ")");
        return s;
    }

    /**
     * Starts serving without a sim thread: the caller advances the world with {@link #step(long)}.
     *
     * @param world the world (owned by the server from now on)
     * @param config address, port, model name and limits
     * @return the running server
     * @throws IOException if the port cannot be bound
     */
    public static PlayerSimServer startManual(World world, ServerConfig config) throws IOException {
        return startManual(world, config, ServerEnvironment.system());
    }

    /** {@link #startManual(World, ServerConfig)} with parts of the environment replaced (tests). */
    static PlayerSimServer startManual(World world, ServerConfig config, ServerEnvironment env) throws IOException {
        PlayerSimServer s = new PlayerSimServer(world, null, config, env);
        s.startThreads();
        return s;
    }

    /** @return how the sim thread waits for the next step (tests step it on a manual clock), or null without one */
    WorldClockIdleStrategy steppingIdle() {
        return steppingIdle;
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
        return acceptor.sessions().size();
    }

    /** @return simulation time in seconds (the timestamps the server sends) */
    public double simTimeS() {
        return world.timeS();
    }

    /**
     * Where the server's timestamps lie on its clock: the clock's reading at which the world's
     * time was 0, so that a timestamp of {@code t} seconds was taken at the clock's reading
     * {@code origin + t * 1e9} (the sim thread keeps world time at the clock's reading minus the
     * origin, in whole steps). Waits up to 5 s for a just started sim thread to take its
     * first reading.
     *
     * @return the origin in the clock's nanoseconds
     * @throws IllegalStateException for a server stepped by hand ({@link #startManual}), or if the
     *     sim thread does not start (or the calling thread is interrupted while it waits, its
     *     interrupt status then set)
     */
    public long clockOriginNs() {
        if (simThread == null) {
            throw new IllegalStateException("a server stepped by hand follows no clock");
        }
        long origin;
        try {
            origin = stepper.awaitClockOriginNs(ORIGIN_WAIT_NS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while waiting for the sim thread to start", e);
        }
        if (origin == Long.MIN_VALUE) {
            throw new IllegalStateException("the sim thread did not start within 5 s");
        }
        return origin;
    }

    /** @return the robot's ground-truth pose */
    public Pose2d groundTruth() {
        return world.read(World::pose);
    }

    /**
     * Runs a function on the world under the server's lock (e.g. to read the contact count).
     *
     * @param f what to do; must not keep the world
     * @param <T> the result type
     * @return f's result
     */
    public <T> T withWorld(Function<World, T> f) {
        return world.read(f);
    }

    /**
     * Advances the world by {@code dtNs} and sends what it published to subscribed clients.
     * Only for servers started with {@link #startManual(World, ServerConfig)}.
     *
     * @param dtNs world nanoseconds, not negative
     * @throws IllegalStateException if a sim thread steps this server
     */
    public void step(long dtNs) {
        if (stepping != null) {
            throw new IllegalStateException("the sim thread steps this server; step() is for startManual servers");
        }
        stepper.step(dtNs);
    }

    /** Stops the sim thread, disconnects every client and closes the port; idempotent. */
    @Override
    public void close() {
        AgentThread sim = simThread;
        if (sim != null) {
            sim.close();
        }
        acceptor.stop();
        try {
            serverSocket.close(); // ends the accept the loop is blocked in
        } catch (IOException e) {
            LOG.log(Level.DEBUG, "rtaware-sim: closing the server socket: " + e.getMessage());
        }
        acceptThread.close();
    }
}
