package io.rtaware.app.sim;

import io.rtaware.app.UserError;
import io.rtaware.app.cli.DurationConverter;
import io.rtaware.app.cli.TimeScaleConverter;
import io.rtaware.app.foxglove.FoxgloveMixin;
import io.rtaware.app.ros2.DdsMixin;
import io.rtaware.app.ros2.Ros2Options;
import io.rtaware.app.ros2.Ros2SimMixin;
import io.rtaware.app.ros2.Ros2SimServe;
import io.rtaware.app.ros2.RosDistroMixin;
import io.rtaware.core.time.Durations;
import io.rtaware.core.time.ScaledClock;
import io.rtaware.foxglove.FoxgloveServer;
import io.rtaware.robotrun.SimulatorFeed;
import io.rtaware.ros2.graph.Ros2Distro;
import io.rtaware.sim.scenario.Scenario;
import io.rtaware.sim.scenario.ScenarioException;
import io.rtaware.sim.scenario.ScenarioLoader;
import io.rtaware.sim.server.PlayerSimServer;
import io.rtaware.sim.server.ServerConfig;
import io.rtaware.sim.server.SimCommandSupport;
import java.io.IOException;
import java.util.Optional;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code rtaware sim}: serves the simulated world over the Player protocol, for any Player client
 * (rtaware's own with {@code run --player}, or Player's C client).
 */
@Command(name = "sim", mixinStandardHelpOptions = true,
        description = {"Serve a simulated robot world over the Player protocol (127.0.0.1 unless --bind says otherwise).",
                "Example: rtaware sim --scenario paper-room --port 6665 --time-scale 10"})
public final class SimCommand implements Callable<Integer> {

    @Option(names = "--scenario", defaultValue = ScenarioLoader.PAPER_ROOM, paramLabel = "NAME|FILE",
            description = "A built-in scenario (" + ScenarioLoader.BUILT_IN_NAMES + ") or a scenario YAML file (default: ${DEFAULT-VALUE}).")
    String scenario;

    @Option(names = "--port", defaultValue = "6665", paramLabel = "PORT", description = "TCP port, 0 for any free one (default: ${DEFAULT-VALUE}).")
    int port;

    @Option(names = "--time-scale", converter = TimeScaleConverter.class, defaultValue = "1", paramLabel = "K", description = "World runs K times faster than wall time (default: ${DEFAULT-VALUE}).")
    double timeScale;

    @Option(names = "--seed", defaultValue = "1", paramLabel = "S", description = "Seed of the sensor noise (default: ${DEFAULT-VALUE}).")
    long seed;

    @Option(names = "--robot-seed", defaultValue = "4", paramLabel = "S",
            description = "Seed of the simulated robot's systematic odometry errors: the same seed is the same robot, "
                    + "as in 'rtaware run --robot-seed' (default: ${DEFAULT-VALUE}).")
    long robotSeed;

    @Option(names = "--bind", defaultValue = ServerConfig.LOOPBACK, paramLabel = "ADDR",
            description = "Listen address (default: ${DEFAULT-VALUE}); 0.0.0.0 exposes the simulator to other machines.")
    String bind;

    @Option(names = "--max-clients", defaultValue = "" + ServerConfig.DEFAULT_MAX_CLIENTS, paramLabel = "N",
            description = "Clients served at once, each costs two threads; more are refused (default: ${DEFAULT-VALUE}).")
    int maxClients;

    @Option(names = "--max-rules", defaultValue = "" + ServerConfig.DEFAULT_MAX_RULES, paramLabel = "N",
            description = "Replace rules per client; more are NACKed (default: ${DEFAULT-VALUE}).")
    int maxRules;

    @Option(names = "--message-timeout", defaultValue = "10s", converter = DurationConverter.class, paramLabel = "DURATION",
            description = "A client that sends part of a message and not the rest within this time is disconnected (default: ${DEFAULT-VALUE}).")
    long messageTimeoutNs;

    @Mixin
    Ros2SimMixin ros2;

    @Mixin
    FoxgloveMixin foxglove;

    @Mixin
    RosDistroMixin rosDistro;

    @Mixin
    DdsMixin dds;

    @Override
    public Integer call() {
        if (port < 0 || port > 65535) {
            throw new UserError("--port must be 0..65535, got " + port);
        }
        if (maxClients < 1 || maxClients > ServerConfig.MAX_CLIENTS_LIMIT) {
            throw new UserError("--max-clients must be 1.." + ServerConfig.MAX_CLIENTS_LIMIT + ", got " + maxClients);
        }
        if (maxRules < 1 || maxRules > 65536) {
            throw new UserError("--max-rules must be 1..65536, got " + maxRules);
        }
        if (messageTimeoutNs < 1_000_000L || messageTimeoutNs > 3_600_000_000_000L) {
            throw new UserError("--message-timeout must be 1ms..60min, got " + Durations.format(messageTimeoutNs));
        }
        ServerConfig config = ServerConfig.defaults(port).withBindAddress(bind)
                .withLimits(maxClients, maxRules, messageTimeoutNs);
        try {
            Ros2Distro distro = rosDistro.distro(ros2.requested(), "--ros2");
            Optional<Ros2Options> ros2Options = ros2.options(distro,
                    dds.settings(ros2.requested(), "--ros2", ros2.domain(), distro));
            serveUntilInterrupted(config, ros2Options);
        } catch (ScenarioException e) {
            throw new UserError(e.getMessage());
        } catch (IOException e) {
            throw new UserError("cannot serve on " + bind + ":" + port + ": " + e.getMessage());
        }
        return 0;
    }

    /**
     * Serves the world over the Player protocol and, as asked, as a ROS 2 robot and to Foxglove,
     * until the thread is interrupted (Ctrl-C); then closes Foxglove, the ROS 2 robot and the
     * simulator, in that order.
     */
    private void serveUntilInterrupted(ServerConfig config, Optional<Ros2Options> ros2Options) throws IOException {
        if (foxglove.enabled()) {
            foxglove.address(); // a bad --foxglove ends the command before the simulator starts
        }
        Scenario s = ScenarioLoader.load(scenario);
        ScaledClock clock = new ScaledClock(timeScale);
        // Closed in reverse order (the Foxglove feed, its server, the ROS 2 robot, the simulator), each
        // waiting for its threads even though Ctrl-C has interrupted this one (AgentThread.close).
        try (PlayerSimServer server = SimCommandSupport.start(s, clock, config, seed, robotSeed);
             Ros2SimServe robot = ros2Options.isPresent() ? Ros2SimServe.start(server, ros2Options.get(), System.out)
                     : null;
             FoxgloveServer foxgloveServer = foxglove.enabled() ? foxglove.start("sim", System.out, System.err) : null;
             SimulatorFeed feed = foxgloveServer != null ? SimulatorFeed.start(s, server, clock, foxgloveServer) : null) {
            System.out.println(SimCommandSupport.startLine(s, config, server.port(), timeScale, seed));
            if (robot != null) {
                System.out.println(robot.startLine());
            }
            System.out.flush();
            SimCommandSupport.waitUntilInterrupted();
        }
    }
}
