package io.rtaware.robotrun;

import io.rtaware.core.time.Clock;
import io.rtaware.player.client.PlayerClient;
import io.rtaware.player.client.PlayerClientOptions;
import io.rtaware.player.client.PlayerCounters;
import io.rtaware.player.protocol.DeviceAddress;
import io.rtaware.player.protocol.SimulationPose2d;
import io.rtaware.player.task.DeviceSamples;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.robot.validate.SampleChecks;
import io.rtaware.robot.validate.SampleLimits;
import io.rtaware.robot.validate.SampleValidator;
import java.io.IOException;
import java.util.concurrent.TimeUnit;

/**
 * The robot's true pose from a Player server's {@code simulation:0} device, on a connection of
 * the referee's own. When the connection is lost (the simulator killed and restarted), it is
 * reopened like the controller's: the first attempt {@link #INITIAL_BACKOFF_MS} of world time
 * after the loss, each failed attempt doubling the wait up to {@link #MAX_BACKOFF_MS}. Until then
 * {@link #pose()} returns null, which the referee records as a gap. A pose that cannot be true
 * ({@link SampleChecks#pose}) is rejected and counted, never returned. Used by the referee's
 * thread only.
 */
final class GroundTruthSource implements Referee.PoseSource {

    /** First wait before reopening a lost connection, in world milliseconds. */
    static final long INITIAL_BACKOFF_MS = 500;
    /** Longest wait between attempts, in world milliseconds. */
    static final long MAX_BACKOFF_MS = 8000;
    private static final DeviceAddress SIMULATION = DeviceAddress.parse("simulation:0");

    private final String host;
    private final int port;
    private final String model;
    private final Clock clock;
    private final SampleValidator checks = new SampleValidator("simulation:0", SampleLimits.defaults());
    private PlayerClient client;
    private long backoffMs = INITIAL_BACKOFF_MS;
    private long nextAttemptNs;
    private volatile long reconnects;

    private GroundTruthSource(String host, int port, String model, Clock clock, PlayerClient client) {
        this.host = host;
        this.port = port;
        this.model = model;
        this.clock = clock;
        this.client = client;
    }

    /**
     * Connects and asks for the model's pose once.
     *
     * @param host server host
     * @param port server port
     * @param model the robot's model name
     * @param clock the world clock (for the back-off)
     * @return the source
     * @throws IOException if the server has no {@code simulation:0} or does not know the model
     */
    static GroundTruthSource open(String host, int port, String model, Clock clock) throws IOException {
        return new GroundTruthSource(host, port, model, clock, connect(host, port, model));
    }

    private static PlayerClient connect(String host, int port, String model) throws IOException {
        PlayerClient c = PlayerClient.connect(host, port, PlayerClientOptions.defaults(), new PlayerCounters());
        try {
            c.subscribe(SIMULATION);
            c.simulationPose2d(0, model);
            return c;
        } catch (IOException | RuntimeException e) {
            c.close();
            throw e;
        }
    }

    @Override
    public Pose2d pose() throws IOException {
        if (client == null && !reconnectIfDue()) {
            return null;
        }
        SimulationPose2d p;
        try {
            p = client.simulationPose2d(0, model);
        } catch (IOException e) {
            drop();
            throw e;
        }
        String bad = SampleChecks.pose(p.xM(), p.yM(), p.yawRad(), SampleLimits.defaults());
        return checks.record(bad, Double.NaN) ? new Pose2d(p.xM(), p.yM(), p.yawRad()) : null;
    }

    private boolean reconnectIfDue() throws IOException {
        long nowNs = clock.nanos();
        if (nowNs - nextAttemptNs < 0) {
            return false;
        }
        try {
            client = connect(host, port, model);
        } catch (IOException e) {
            nextAttemptNs = nowNs + TimeUnit.MILLISECONDS.toNanos(backoffMs);
            backoffMs = Math.min(backoffMs * 2, MAX_BACKOFF_MS);
            throw e;
        }
        backoffMs = INITIAL_BACKOFF_MS;
        reconnects++;
        return true;
    }

    private void drop() {
        try {
            client.close();
        } catch (IOException ignored) {
            // the connection is already unusable
        }
        client = null;
        nextAttemptNs = clock.nanos() + TimeUnit.MILLISECONDS.toNanos(backoffMs);
    }

    @Override
    public String kind() {
        return "ground_truth";
    }

    /** @return how often the connection was reopened after a loss */
    long reconnects() {
        return reconnects;
    }

    /** @return ground-truth poses received and rejected because they cannot be true */
    DeviceSamples samples() {
        return DeviceSamples.of(checks);
    }

    @Override
    public void close() throws IOException {
        if (client != null) {
            client.close();
            client = null;
        }
    }
}
