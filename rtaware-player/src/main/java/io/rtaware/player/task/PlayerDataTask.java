package io.rtaware.player.task;

import io.rtaware.core.data.Input;
import io.rtaware.core.data.Output;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.time.Clock;
import io.rtaware.player.client.PlayerClient;
import io.rtaware.player.client.PlayerConnectionException;
import io.rtaware.player.client.PlayerCounters;
import io.rtaware.player.client.PlayerStats;
import io.rtaware.player.client.PlayerTimeoutException;
import io.rtaware.player.protocol.DeviceAddress;
import io.rtaware.player.protocol.Interfaces;
import io.rtaware.player.protocol.ReplaceRule;
import io.rtaware.player.protocol.Subtypes;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.robot.msg.RobotKeys;
import io.rtaware.robot.msg.VelocityCommand;
import io.rtaware.robot.validate.ImpossibleDataException;
import io.rtaware.robot.validate.RejectionWatch;
import io.rtaware.robot.validate.SampleValidator;
import java.io.IOException;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;

/**
 * The task that connects a Player server to the data store; run it with
 * {@code Schedule.continuous()}. It owns the connection: {@link #initialize} connects,
 * subscribes to position2d and the scan source and declares that it produces
 * {@link RobotKeys#ODOMETRY} and {@link RobotKeys#LASER} and consumes {@link RobotKeys#MOTOR}.
 * Each {@link #execute} waits at most {@link PlayerConfig#pollWaitMs()} of wall time for data,
 * publishes the newest odometry and scan when new ones arrived, and sends CMD VEL when the
 * motor command has a new generation with a changed value, or again after
 * {@link PlayerConfig#keepAliveMs()} of world time. A lost connection (or no message for
 * {@link PlayerConfig#readTimeoutMs()}) is thrown from {@code execute}, so the monitor
 * counts it and the keys go stale; with reconnection enabled, later cycles reconnect with
 * exponential back-off. {@link #terminate} sends a zero velocity first, then unsubscribes and
 * closes.
 *
 * <p>Samples that cannot be true ({@link io.rtaware.robot.validate.SampleChecks}) are rejected
 * by the client where they are decoded and never published; {@link #deviceSamples()} counts
 * them per device. When a device has delivered only rejected samples for
 * {@link #IMPOSSIBLE_DATA_FAULT_AFTER_NS} of world time, the task halts the robot: it sends a
 * zero velocity at once, from then on sends only zero velocities, records {@link #fault()} (one
 * line naming the device and the value) and throws {@link ImpossibleDataException} from that
 * cycle, so the monitor counts the error. The halt lasts until {@link #terminate}.
 *
 * <p>Called by one thread at a time, as every task; {@link #stats()} may be called from any
 * thread.
 */
public final class PlayerDataTask implements Task {

    /** World time of rejection-only samples from one device after which the robot is halted: 1 s. */
    public static final long IMPOSSIBLE_DATA_FAULT_AFTER_NS = 1_000_000_000L;

    private final PlayerConfig config;
    private final PlayerCounters counters = new PlayerCounters();
    private final DeviceAddress position2d;

    private Output<Odometry> odometryOut;
    private Output<LaserScan> laserOut;
    private Input<VelocityCommand> motorIn;

    private PlayerClient client;
    private volatile String serverVersion = "";
    private long seenOdometry;
    private long seenScans;
    private boolean pullPending;
    private long lastMessageNs = Long.MIN_VALUE;

    private long motorGeneration = -1;
    private boolean commandSent;
    private double sentVxMps;
    private double sentOmegaRadPerSec;
    private long sentAtNs;

    private long backoffMs;
    private long nextAttemptNs;
    private int failedAttempts;

    private final RejectionWatch odometryWatch = new RejectionWatch(IMPOSSIBLE_DATA_FAULT_AFTER_NS);
    private final RejectionWatch scanWatch = new RejectionWatch(IMPOSSIBLE_DATA_FAULT_AFTER_NS);
    private volatile String fault;

    /** World clock of the monitor, to turn world-time silence into the wall time a socket sees. */
    private Clock clock;

    /**
     * @param config connection settings (validated when built)
     */
    public PlayerDataTask(PlayerConfig config) {
        this.config = config;
        this.position2d = DeviceAddress.of(Interfaces.POSITION2D, config.position2dIndex());
        this.backoffMs = config.reconnectInitialBackoffMs();
    }

    /**
     * Declares the keys and connects. Without reconnection a failure to connect fails the
     * initialization; with it, the first attempt's failure is counted and later cycles retry.
     *
     * @param setup the declarations interface
     * @throws IOException if the server cannot be reached and reconnection is disabled
     */
    @Override
    public void initialize(TaskSetup setup) throws IOException {
        clock = setup.clock();
        odometryOut = setup.produce(RobotKeys.ODOMETRY);
        laserOut = setup.produce(RobotKeys.LASER);
        motorIn = setup.consume(RobotKeys.MOTOR);
        try {
            open();
        } catch (IOException e) {
            counters.connectionLost();
            if (!config.reconnect()) {
                throw e;
            }
            nextAttemptNs = setup.clock().nanos();
        }
    }

    private void open() throws IOException {
        PlayerClient c = PlayerClient.connect(config.host(), config.port(), config.clientOptions(), counters);
        try {
            if (config.dataMode() == DataMode.PULL) {
                c.setDataMode(Subtypes.DATAMODE_PULL);
            } else {
                c.setDataMode(Subtypes.DATAMODE_PUSH);
                c.addReplaceRule(ReplaceRule.latestDataOnly());
            }
            c.subscribe(position2d);
            c.subscribe(config.scanSource());
            if (config.scanSource().interf() == Interfaces.RANGER) {
                c.rangerConfig(config.scanSource().index());
            }
        } catch (IOException | RuntimeException e) {
            c.close();
            throw e;
        }
        client = c;
        serverVersion = c.serverVersion();
        seenOdometry = 0;
        seenScans = 0;
        pullPending = false;
        lastMessageNs = Long.MIN_VALUE;
        sentAtNs = Long.MIN_VALUE;
        odometryWatch.reset();
        scanWatch.reset();
    }

    /**
     * One cycle: reconnect if due, send the motor command if needed, read, publish.
     *
     * @param nowNs world time at the start of the cycle
     * @throws IOException if the connection is lost, times out, is broken, or a reconnection
     *     attempt fails; or if it is down and reconnection is disabled
     * @throws InterruptedException if interrupted while waiting to reconnect
     * @throws ImpossibleDataException in the cycle that halts the robot because a device sent
     *     only impossible samples for {@link #IMPOSSIBLE_DATA_FAULT_AFTER_NS}
     */
    /** @return true: a cycle waits on the socket for the server's next data, so it keeps a thread of its own */
    @Override
    public boolean blocks() {
        return true;
    }

    @Override
    public void execute(long nowNs) throws IOException, InterruptedException, ImpossibleDataException {
        if (client == null && !reconnectIfDue(nowNs)) {
            return;
        }
        try {
            sendMotor(nowNs);
            int n;
            if (config.dataMode() == DataMode.PULL) {
                if (!pullPending) {
                    client.requestData();
                    pullPending = true;
                }
                long synchs = client.synchs();
                n = client.poll(config.pollWaitMs(), true);
                if (client.synchs() != synchs) {
                    pullPending = false;
                }
            } else {
                n = client.poll(config.pollWaitMs(), false);
            }
            checkReadTimeout(nowNs, n);
            publish();
            watchRejections(nowNs);
        } catch (IOException e) {
            drop(nowNs);
            throw e;
        }
    }

    private SampleValidator scanChecks() {
        return config.scanSource().interf() == Interfaces.RANGER ? counters.rangerChecks() : counters.laserChecks();
    }

    private void watchRejections(long nowNs) throws IOException, ImpossibleDataException {
        boolean odometryFault = odometryWatch.observe(nowNs, counters.odometryChecks().lastRejected());
        boolean scanFault = scanWatch.observe(nowNs, scanChecks().lastRejected());
        if (fault != null || !(odometryFault || scanFault)) {
            return;
        }
        SampleValidator checks = odometryFault ? counters.odometryChecks() : scanChecks();
        long sinceNs = (odometryFault ? odometryWatch : scanWatch).rejectingSinceNs();
        fault = String.format(Locale.ROOT, "%s sent only impossible samples for %.1f s of world time (%d"
                        + " rejected in all), latest: %s; robot halted",
                odometryFault ? position2d : config.scanSource(), (nowNs - sinceNs) / 1e9, checks.rejected(),
                checks.lastRejection());
        sendVelocity(0.0, 0.0, nowNs);
        throw new ImpossibleDataException(fault);
    }

    private boolean reconnectIfDue(long nowNs) throws IOException, InterruptedException {
        if (!config.reconnect()) {
            throw new PlayerConnectionException("not connected to Player server " + config.host() + ":"
                    + config.port() + " (reconnection disabled)", null);
        }
        if (nowNs - nextAttemptNs < 0) {
            long waitMs = Math.min(config.pollWaitMs(), TimeUnit.NANOSECONDS.toMillis(nextAttemptNs - nowNs) + 1);
            Thread.sleep(waitMs);
            return false;
        }
        try {
            open();
            failedAttempts = 0;
            backoffMs = config.reconnectInitialBackoffMs();
            return true;
        } catch (IOException e) {
            failedAttempts++;
            counters.connectionLost();
            long waitMs = backoffMs;
            nextAttemptNs = nowNs + TimeUnit.MILLISECONDS.toNanos(waitMs);
            backoffMs = Math.min(backoffMs * 2, config.reconnectMaxBackoffMs());
            throw new PlayerConnectionException("reconnection attempt " + failedAttempts + " to " + config.host() + ":"
                    + config.port() + " failed, next in " + waitMs + " ms: " + e.getMessage(), e);
        }
    }

    private void checkReadTimeout(long nowNs, int messages) throws PlayerTimeoutException {
        if (messages > 0 || lastMessageNs == Long.MIN_VALUE) {
            lastMessageNs = nowNs;
            return;
        }
        // A socket's silence is a wall-time fact: with a scaled clock, 2 s of world time may be
        // only a short stall of a loaded machine.
        long silentWallNs = clock.toWallNanos(nowNs - lastMessageNs);
        if (silentWallNs > TimeUnit.MILLISECONDS.toNanos(config.readTimeoutMs())) {
            throw new PlayerTimeoutException("no message from Player server " + client.server() + " for "
                    + TimeUnit.NANOSECONDS.toMillis(silentWallNs) + " ms of wall time (read timeout "
                    + config.readTimeoutMs() + " ms)");
        }
    }

    private void sendMotor(long nowNs) throws IOException {
        if (fault != null) {
            // halted: only zero velocities, again after the keep-alive period
            if (sentVxMps != 0.0 || sentOmegaRadPerSec != 0.0 || sentAtNs == Long.MIN_VALUE
                    || nowNs - sentAtNs >= TimeUnit.MILLISECONDS.toNanos(config.keepAliveMs())) {
                sendVelocity(0.0, 0.0, nowNs);
            }
            return;
        }
        if (motorIn.hasValue() && motorIn.generation() != motorGeneration) {
            motorGeneration = motorIn.generation();
            VelocityCommand cmd = motorIn.value();
            if (!commandSent || cmd.vxMps != sentVxMps || cmd.omegaRadPerSec != sentOmegaRadPerSec) {
                sendVelocity(cmd.vxMps, cmd.omegaRadPerSec, nowNs);
                return;
            }
        }
        if (commandSent && (sentAtNs == Long.MIN_VALUE
                || nowNs - sentAtNs >= TimeUnit.MILLISECONDS.toNanos(config.keepAliveMs()))) {
            sendVelocity(sentVxMps, sentOmegaRadPerSec, nowNs);
        }
    }

    private void sendVelocity(double vxMps, double omegaRadPerSec, long nowNs) throws IOException {
        client.sendVelocity(config.position2dIndex(), vxMps, 0.0, omegaRadPerSec, 1);
        commandSent = true;
        sentVxMps = vxMps;
        sentOmegaRadPerSec = omegaRadPerSec;
        sentAtNs = nowNs;
    }

    private void publish() {
        if (client.odometryUpdates() != seenOdometry) {
            seenOdometry = client.odometryUpdates();
            odometryOut.value().copyFrom(client.odometry());
            odometryOut.publish();
        }
        boolean ranger = config.scanSource().interf() == Interfaces.RANGER;
        long scans = ranger ? client.rangerUpdates() : client.laserUpdates();
        if (scans != seenScans) {
            seenScans = scans;
            laserOut.value().copyFrom(ranger ? client.rangerScan() : client.laserScan());
            laserOut.publish();
        }
    }

    private void drop(long nowNs) {
        counters.connectionLost();
        try {
            client.close();
        } catch (IOException ignored) {
            // the connection is already unusable; closing is best effort
        }
        client = null;
        nextAttemptNs = nowNs + TimeUnit.MILLISECONDS.toNanos(backoffMs);
    }

    /**
     * @return true: this task commands the robot, so a stop terminates it (the zero velocity
     *     below) before it waits for the other tasks' last cycles
     */
    @Override
    public boolean stopsFirst() {
        return true;
    }

    /**
     * Stops the robot and leaves: sends a zero velocity command first, then unsubscribes from
     * the scan source and position2d, then closes the connection.
     *
     * @throws IOException the first failure, after every step was attempted
     */
    @Override
    public void terminate() throws IOException {
        if (client == null) {
            return;
        }
        IOException first = null;
        try {
            client.sendVelocity(config.position2dIndex(), 0.0, 0.0, 0.0, 1);
        } catch (IOException e) {
            first = e;
        }
        if (first == null) {
            try {
                client.unsubscribe(config.scanSource());
                client.unsubscribe(position2d);
            } catch (IOException e) {
                first = e;
            }
        }
        try {
            client.close();
        } catch (IOException e) {
            first = first == null ? e : first;
        }
        client = null;
        if (first != null) {
            throw first;
        }
    }

    /** @return a snapshot of the counters of every connection this task made */
    public PlayerStats stats() {
        return counters.snapshot();
    }

    /**
     * @return one line naming the device and the value that halted the robot, or null while no
     *     device has sent only impossible samples for {@link #IMPOSSIBLE_DATA_FAULT_AFTER_NS};
     *     readable from any thread
     */
    public String fault() {
        return fault;
    }

    /**
     * @return per device ({@code position2d:N} and the scan source), the samples received and
     *     rejected so far over every connection; readable from any thread
     */
    public Map<String, DeviceSamples> deviceSamples() {
        Map<String, DeviceSamples> devices = new LinkedHashMap<>();
        devices.put(position2d.toString(), DeviceSamples.of(counters.odometryChecks()));
        devices.put(config.scanSource().toString(), DeviceSamples.of(scanChecks()));
        return devices;
    }

    /** @return the version the server announced ("" before the first connection) */
    public String serverVersion() {
        return serverVersion;
    }

    /** @return the configuration */
    public PlayerConfig config() {
        return config;
    }
}
