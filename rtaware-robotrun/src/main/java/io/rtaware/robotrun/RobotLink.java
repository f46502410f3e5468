package io.rtaware.robotrun;

import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.task.ErrorPolicy;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.Clock;
import io.rtaware.player.client.PlayerClient;
import io.rtaware.player.client.PlayerClientOptions;
import io.rtaware.player.client.PlayerCounters;
import io.rtaware.player.client.PlayerStats;
import io.rtaware.player.task.DeviceSamples;
import io.rtaware.player.task.PlayerConfig;
import io.rtaware.player.task.PlayerDataTask;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.robot.msg.RobotKeys;
import io.rtaware.sim.server.PlayerSimServer;
import io.rtaware.sim.server.ServerConfig;
import io.rtaware.sim.world.RobotModel;
import java.io.IOException;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;

/**
 * How the controller reaches its robot: the built-in simulator over the Player protocol on
 * loopback, an external Player server, or a ROS 2 robot ({@link Ros2Link}: the built-in simulator
 * served as one, or a robot through a Zenoh router or over DDS). Gives the monitor's data task
 * (continuous, {@link ErrorPolicy#CONTINUE}: it reconnects on its own), the data task's safety
 * fault (data that cannot be true), and the referee's source of the true pose: the Player
 * server's {@code simulation:0} on a connection of its own when there is one (the built-in
 * simulator, also when it serves as a ROS 2 robot; Stage), none otherwise (the referee then
 * watches the robot's odometry, which is not recorded as ground truth). Owns what it was given: {@link #close()} stops the ROS 2 side, then the
 * simulator. Not thread-safe: opened and closed by the run's thread.
 */
public final class RobotLink implements AutoCloseable {

    /** Task name of the Player data task in reports. */
    public static final String PLAYER_TASK = "player";

    private final PlayerSimServer simulator;
    /** The Player server, or null for a ROS 2 robot without one. */
    private final String host;
    private final int port;
    private final Ros2Link ros2;
    private final PlayerDataTask player;

    private RobotLink(PlayerSimServer simulator, String host, int port, Ros2Link ros2) {
        this.simulator = simulator;
        this.host = host;
        this.port = port;
        this.ros2 = ros2;
        this.player = ros2 != null ? null
                : new PlayerDataTask(PlayerConfig.of(host, port).withReconnect(true, 500, 8000));
    }

    /**
     * The built-in simulator, reached over the Player protocol on loopback like any Player server.
     *
     * @param simulator the running simulator (e.g. from
     *     {@link io.rtaware.sim.server.SimCommandSupport#start}); closed with the link
     * @return the link
     */
    public static RobotLink simulator(PlayerSimServer simulator) {
        return new RobotLink(simulator, ServerConfig.LOOPBACK, simulator.port(), null);
    }

    /**
     * An external Player server, which must answer now: once running, the data task reconnects
     * with back-off, but a server that cannot be reached at the start is a wrong address or a
     * server not started.
     *
     * @param host the server's host
     * @param port its port
     * @return the link
     * @throws IOException if the server cannot be reached or does not speak Player
     */
    public static RobotLink player(String host, int port) throws IOException {
        try (PlayerClient probe = PlayerClient.connect(host, port, PlayerClientOptions.defaults(), new PlayerCounters())) {
            probe.serverVersion();
        }
        return new RobotLink(null, host, port, null);
    }

    /**
     * A ROS 2 robot.
     *
     * @param ros2 the ROS 2 side: the data task's session, and the simulator's ROS 2 robot if it serves as one
     * @param simulator the built-in simulator serving as the ROS 2 robot (its Player port then
     *     gives the true pose), or null for another robot
     * @return the link; closes both
     */
    public static RobotLink ros2(Ros2Link ros2, PlayerSimServer simulator) {
        return new RobotLink(simulator, simulator == null ? null : ServerConfig.LOOPBACK,
                simulator == null ? 0 : simulator.port(), ros2);
    }

    /** @return the data task as the monitor runs it: Player's or the ROS 2 one */
    public TaskSpec dataTask() {
        return ros2 != null ? ros2.taskSpec()
                : new TaskSpec(PLAYER_TASK, Schedule.continuous(), ErrorPolicy.CONTINUE, player);
    }

    /** @return the data task's name in reports */
    public String dataTaskName() {
        return ros2 != null ? Ros2Link.TASK : PLAYER_TASK;
    }

    /** @return one line describing a safety fault of the robot's data (it sent only impossible data), or null */
    public String safetyFault() {
        return player != null ? player.fault() : ros2.task().fault();
    }

    /** @return the built-in simulator, if the robot is it */
    public Optional<PlayerSimServer> simulator() {
        return Optional.ofNullable(simulator);
    }

    /** @return the ROS 2 side, if the robot is a ROS 2 robot */
    public Optional<Ros2Link> ros2() {
        return Optional.ofNullable(ros2);
    }

    /**
     * @param model the simulated robot's model (named when the robot is the simulator)
     * @return where the robot is, for a start line
     */
    public String describe(RobotModel model) {
        if (ros2 != null) {
            return ros2.describe();
        }
        return host + ":" + port + " (" + (simulator != null ? "built-in simulator, " + model.describe()
                : "external Player server") + ")";
    }

    /**
     * @return the robot as a recording's {@code robot} metadata names it: {@code built-in simulator}
     *     (over Player), {@code Player at HOST:PORT}, or the ROS 2 robot's description (the
     *     built-in simulator as a ROS 2 robot over Zenoh, a ROS 2 robot through Zenoh at a
     *     router or over DDS)
     */
    public String recordedAs() {
        if (ros2 != null) {
            return ros2.describe();
        }
        return simulator != null ? "built-in simulator" : String.format(Locale.ROOT, "Player at %s:%d", host, port);
    }

    /**
     * The source of the robot's true pose, connected now (before the monitor starts, so that the
     * referee's first sample is the pose at the start): the Player server's {@code simulation:0}
     * on a connection of its own.
     *
     * @param modelName the robot's model name in the simulation
     * @param clock the world clock (for reconnection back-off)
     * @return the source, or null when nothing knows the true pose: no Player server (a ROS 2
     *     robot other than the built-in simulator), or one without {@code simulation:0} or this model
     */
    public Referee.PoseSource groundTruth(String modelName, Clock clock) {
        if (host == null) {
            return null;
        }
        try {
            return GroundTruthSource.open(host, port, modelName, clock);
        } catch (IOException e) {
            return null; // no second connection or no simulation:0: no truth source
        }
    }

    /**
     * The referee's source of the robot's pose when nothing knows the true one: the robot's
     * odometry as the monitor holds it (kind {@code odometry}).
     *
     * @param monitor the monitor holding {@link RobotKeys#ODOMETRY}
     * @return the source
     */
    public static Referee.PoseSource odometry(Monitor monitor) {
        Odometry odometry = new Odometry();
        return new Referee.PoseSource() {
            @Override
            public Pose2d pose() {
                return monitor.read(RobotKeys.ODOMETRY, odometry) == 0 ? null : odometry.pose();
            }

            @Override
            public String kind() {
                return "odometry";
            }
        };
    }

    /**
     * @param truth the referee's pose source (its {@code simulation:0} samples are added when it is the Player server's)
     * @return the report's {@code player} section, or null when the robot is not a Player server
     */
    public PlayerSection playerSection(Referee.PoseSource truth) {
        if (player == null) {
            return null;
        }
        PlayerStats stats = player.stats();
        Map<String, DeviceSamples> devices = new LinkedHashMap<>(player.deviceSamples());
        if (truth instanceof GroundTruthSource groundTruth) {
            devices.put("simulation:0", groundTruth.samples());
        }
        return new PlayerSection(host + ":" + port, player.serverVersion(), stats.connects(), stats.connectionLosses(),
                stats.protocolErrors(), devices, player.fault());
    }

    /** Stops the ROS 2 side, if any, then the simulator, if any. */
    @Override
    public void close() {
        try {
            if (ros2 != null) {
                ros2.close();
            }
        } finally {
            if (simulator != null) {
                simulator.close();
            }
        }
    }
}
