package io.rtaware.sim.server;

import io.rtaware.core.time.Clock;
import io.rtaware.core.time.ScaledClock;
import io.rtaware.sim.map.OccupancyMap;
import io.rtaware.sim.scenario.Scenario;
import io.rtaware.sim.scenario.ScenarioLoader;
import io.rtaware.sim.world.LaserConfig;
import io.rtaware.sim.world.RobotModel;
import io.rtaware.sim.world.World;
import java.io.IOException;
import java.io.PrintStream;

/**
 * One-call wiring for the command line: {@code rtaware sim} ({@link #serveUntilInterrupted})
 * and an in-process robot for {@code rtaware run} ({@link #start(Scenario, Clock, ServerConfig,
 * long)}). Uses the Koala robot and the URG-04LX laser defaults. Stateless and thread-safe.
 */
public final class SimCommandSupport {

    private SimCommandSupport() {
    }

    /**
     * Builds the world of a scenario and serves it, stepping on {@code clock}, with the
     * scenario's robot model (default: the Koala at the paper's top speed).
     *
     * @param scenario the scenario; it must have a map
     * @param clock world time (share it with the controller in the same process)
     * @param config address, port and limits
     * @param seed seed of all sensor noise
     * @param robotSeed seed of the robot's systematic odometry errors (one robot per seed)
     * @return the running server; close it when done
     * @throws IOException if the port cannot be bound
     * @throws IllegalArgumentException if the scenario has no map
     */
    public static PlayerSimServer start(Scenario scenario, Clock clock, ServerConfig config, long seed, long robotSeed)
            throws IOException {
        return start(scenario, scenario.robot().orElseGet(() -> RobotModel.koala(RobotModel.PAPER_TOP_SPEED_MPS)),
                clock, config, seed, robotSeed);
    }

    /**
     * Builds the world of a scenario with a given robot model and serves it.
     *
     * @param scenario the scenario; it must have a map
     * @param model the robot model
     * @param clock world time
     * @param config address, port and limits
     * @param seed seed of all noise and of the run's odometry errors
     * @return the running server; close it when done
     * @throws IOException if the port cannot be bound
     * @throws IllegalArgumentException if the scenario has no map
     */
    public static PlayerSimServer start(Scenario scenario, RobotModel model, Clock clock, ServerConfig config,
                                        long seed) throws IOException {
        return start(scenario, model, clock, config, seed, seed);
    }

    /**
     * Builds the world of a scenario with a given robot model and robot seed and serves it.
     *
     * @param scenario the scenario; it must have a map
     * @param model the robot model
     * @param clock world time
     * @param config address, port and limits
     * @param seed seed of this run's noise
     * @param robotSeed seed of the robot's systematic odometry errors (one robot per seed)
     * @return the running server; close it when done
     * @throws IOException if the port cannot be bound
     * @throws IllegalArgumentException if the scenario has no map
     */
    public static PlayerSimServer start(Scenario scenario, RobotModel model, Clock clock, ServerConfig config,
                                        long seed, long robotSeed) throws IOException {
        return PlayerSimServer.start(world(scenario, model, seed, robotSeed), clock, config);
    }

    /**
     * The world of a scenario, with its actors, at time zero.
     *
     * @param scenario the scenario; it must have a map
     * @param model the robot model
     * @param seed seed of this run's noise
     * @param robotSeed seed of the robot's systematic odometry errors
     * @return the world
     * @throws IllegalArgumentException if the scenario has no map
     */
    public static World world(Scenario scenario, RobotModel model, long seed, long robotSeed) {
        OccupancyMap map = scenario.map().orElseThrow(() -> new IllegalArgumentException(
                "scenario '" + scenario.name() + "' has no map: the simulator needs one"));
        return new World(map, scenario.start(), model, LaserConfig.URG_04LX, seed, robotSeed, scenario.actors());
    }

    /**
     * {@code rtaware sim --scenario S --port P --time-scale K --seed N --bind ADDR --max-clients C
     * --max-rules R --message-timeout T}: serves until the thread is interrupted (or the JVM
     * exits), then closes the server.
     *
     * @param scenario {@code paper-room} or a scenario file
     * @param config address (use {@link ServerConfig#LOOPBACK} unless told otherwise), port (0 =
     *     any free port; the bound port is printed) and limits
     * @param timeScale world seconds per wall second, positive
     * @param seed seed of all sensor noise
     * @param robotSeed seed of the robot's systematic odometry errors
     * @param out where the one-line start message goes
     * @throws IOException if the port cannot be bound
     * @throws io.rtaware.sim.scenario.ScenarioException if the scenario cannot be loaded
     */
    public static void serveUntilInterrupted(String scenario, ServerConfig config, double timeScale, long seed,
                                             long robotSeed, PrintStream out) throws IOException {
        Scenario s = ScenarioLoader.load(scenario);
        ScaledClock clock = new ScaledClock(timeScale);
        try (PlayerSimServer server = start(s, clock, config, seed, robotSeed)) {
            out.println(startLine(s, config, server.port(), timeScale, seed));
            out.flush();
            waitUntilInterrupted();
        }
    }

    /**
     * @param scenario the served scenario
     * @param config the server's configuration
     * @param port the port it listens on
     * @param timeScale world seconds per wall second
     * @param seed seed of the sensor noise
     * @return the line {@code rtaware sim} prints once the server listens
     */
    public static String startLine(Scenario scenario, ServerConfig config, int port, double timeScale, long seed) {
        return "rtaware-sim: scenario " + scenario.name() + " served on " + config.bindAddress() + ":" + port
                + " (time scale " + timeScale + ", seed " + seed + ", at most " + config.maxClients()
                + " clients); Ctrl-C to stop";
    }

    /** Blocks the calling thread until it is interrupted; returns with its interrupt flag set. */
    public static void waitUntilInterrupted() {
        Object forever = new Object();
        synchronized (forever) {
            try {
                while (true) {
                    forever.wait();
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }
}
