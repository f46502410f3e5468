package io.rtaware.sim.server;

import io.rtaware.core.time.Clock;
import io.rtaware.sim.map.OccupancyMap;
import io.rtaware.sim.scenario.Scenario;
import io.rtaware.sim.world.LaserConfig;
import io.rtaware.sim.world.RobotModel;
import io.rtaware.sim.world.World;
import java.io.IOException;

/**
 * One-call wiring for the command line: the simulator {@code rtaware sim} serves and the
 * in-process robot of {@code rtaware run} ({@link #start(Scenario, Clock, ServerConfig, long, long)}), the
 * line {@code sim} prints when it listens, and waiting until interrupted. Uses the Koala robot and the URG-04LX laser defaults. Stateless and thread-safe.
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
