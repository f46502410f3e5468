package io.rtaware.app.sim;

import io.rtaware.app.UserError;
import io.rtaware.app.cli.TimeScaleConverter;
import io.rtaware.app.ros2.Ros2Options;
import io.rtaware.app.ros2.Ros2SimMixin;
import io.rtaware.app.ros2.Ros2SimServe;
import io.rtaware.sim.scenario.ScenarioException;
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

    @Option(names = "--scenario", defaultValue = "paper-room", description = "Built-in scenario or YAML file (default: ${DEFAULT-VALUE}).")
    String scenario;

    @Option(names = "--port", defaultValue = "6665", description = "TCP port, 0 for any free one (default: ${DEFAULT-VALUE}).")
    int port;

    @Option(names = "--time-scale", converter = TimeScaleConverter.class, defaultValue = "1", paramLabel = "K", description = "World runs K times faster than wall time (default: ${DEFAULT-VALUE}).")
    double timeScale;

    @Option(names = "--seed", defaultValue = "1", description = "Seed of the sensor noise (default: ${DEFAULT-VALUE}).")
    long seed;

    @Option(names = "--bind", defaultValue = ServerConfig.LOOPBACK, paramLabel = "ADDR",
            description = "Listen address (default: ${DEFAULT-VALUE}); 0.0.0.0 exposes the simulator to other machines.")
    String bind;

    @Mixin
    Ros2SimMixin ros2;

    @Override
    public Integer call() {
        if (port < 0 || port > 65535) {
            throw new UserError("--port must be 0..65535, got " + port);
        }
        try {
            Optional<Ros2Options> ros2Options = ros2.options();
            if (ros2Options.isPresent()) {
                Ros2SimServe.serveUntilInterrupted(scenario, port, timeScale, seed, bind, ros2Options.get(), System.out);
            } else {
                SimCommandSupport.serveUntilInterrupted(scenario, port, timeScale, seed, bind, System.out);
            }
        } catch (ScenarioException e) {
            throw new UserError(e.getMessage());
        } catch (IOException e) {
            throw new UserError("cannot serve on " + bind + ":" + port + ": " + e.getMessage());
        }
        return 0;
    }
}
