package io.rtaware.app.ros2;

import io.rtaware.core.time.ScaledClock;
import io.rtaware.ros2.graph.Ros2Context;
import io.rtaware.sim.ros2.Ros2SimRobot;
import io.rtaware.sim.scenario.Scenario;
import io.rtaware.sim.scenario.ScenarioLoader;
import io.rtaware.sim.server.PlayerSimServer;
import io.rtaware.sim.server.ServerConfig;
import io.rtaware.sim.server.SimCommandSupport;
import io.rtaware.zenoh.ZenohException;
import java.io.IOException;
import java.io.PrintStream;
import java.util.List;

/**
 * {@code rtaware sim --ros2}: the simulator served over the Player protocol and, at once, as a
 * ROS 2 robot over Zenoh, until the thread is interrupted or the JVM exits. Stateless.
 */
public final class Ros2SimServe {

    private Ros2SimServe() {
    }

    /**
     * @param scenario {@code paper-room} or a scenario file
     * @param config the Player server's port, listen address and limits
     * @param timeScale world seconds per wall second
     * @param seed seed of the sensor noise
     * @param robotSeed seed of the robot's systematic odometry errors
     * @param ros2 the ROS 2 options
     * @param out where the start lines go
     * @throws IOException if the Player port cannot be bound
     * @throws io.rtaware.sim.scenario.ScenarioException if the scenario cannot be loaded
     * @throws io.rtaware.app.UserError if the Zenoh router cannot be reached or the listen
     *     endpoint cannot be bound
     */
    public static void serveUntilInterrupted(String scenario, ServerConfig config, double timeScale, long seed,
                                             long robotSeed, Ros2Options ros2, PrintStream out) throws IOException {
        Scenario s = ScenarioLoader.load(scenario);
        ScaledClock clock = new ScaledClock(timeScale);
        String listen = ros2.listen() != null ? ros2.listen() : Ros2Wiring.freeLoopbackEndpoint();
        List<String> connect = ros2.routerEndpoint().map(List::of).orElse(List.of());
        String reached = ros2.dds() != null ? ros2.dds().describe()
                : "Zenoh listening on " + listen + (connect.isEmpty() ? "" : ", connected to " + connect.get(0));
        try (PlayerSimServer server = SimCommandSupport.start(s, clock, config, seed, robotSeed)) {
            Ros2Context context = ros2.dds() != null ? Ros2Wiring.openDds(ros2.dds())
                    : Ros2Wiring.open(connect, List.of(listen), ros2.topics().domain(), ros2.distro());
            try (Ros2SimRobot robot = Ros2SimRobot.start(server, context, ros2.topics().namespace(),
                    line -> out.println("rtaware-sim: " + line))) {
                out.println(SimCommandSupport.startLine(s, config, server.port(), timeScale, seed));
                out.println("rtaware-sim: ROS 2 robot node " + Ros2SimRobot.NODE_NAME + " in namespace "
                        + ros2.topics().namespace() + ", domain " + ros2.topics().domain() + ", " + ros2.distro().cliName()
                        + " conventions, " + reached + " (topics scan, odom, ground_truth, cmd_vel)");
                out.flush();
                SimCommandSupport.waitUntilInterrupted();
            }
        } catch (ZenohException e) {
            throw new IOException("the simulator's ROS 2 side: " + e.getMessage(), e);
        }
    }
}
