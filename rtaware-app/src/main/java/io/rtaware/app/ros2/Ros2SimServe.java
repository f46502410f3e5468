package io.rtaware.app.ros2;

import io.rtaware.ros2.graph.Ros2Context;
import io.rtaware.sim.ros2.Ros2SimRobot;
import io.rtaware.sim.server.PlayerSimServer;
import io.rtaware.zenoh.ZenohException;
import java.io.IOException;
import java.io.PrintStream;
import java.util.List;

/**
 * {@code rtaware sim --ros2}: a running simulator served, beside the Player protocol, as a ROS 2
 * robot over Zenoh (or DDS through the bridge) until closed.
 */
public final class Ros2SimServe implements AutoCloseable {

    private final Ros2SimRobot robot;
    private final String line;

    private Ros2SimServe(Ros2SimRobot robot, String line) {
        this.robot = robot;
        this.line = line;
    }

    /**
     * Opens the ROS 2 context and starts the simulated robot's node on the server's world.
     *
     * @param server the running simulator
     * @param ros2 the ROS 2 options
     * @param out where the robot's reports go (one line each)
     * @return the served robot; close it before the simulator
     * @throws IOException if the Zenoh router cannot be reached, the listen endpoint cannot be
     *     bound or the DDS bridge cannot start
     */
    public static Ros2SimServe start(PlayerSimServer server, Ros2Options ros2, PrintStream out) throws IOException {
        String listen = ros2.listen() != null ? ros2.listen() : Ros2Wiring.freeLoopbackEndpoint();
        List<String> connect = ros2.routerEndpoint().map(List::of).orElse(List.of());
        String reached = ros2.dds() != null ? ros2.dds().describe()
                : "Zenoh listening on " + listen + (connect.isEmpty() ? "" : ", connected to " + connect.get(0));
        try {
            Ros2Context context = ros2.dds() != null ? Ros2Wiring.openDds(ros2.dds())
                    : Ros2Wiring.open(connect, List.of(listen), ros2.topics().domain(), ros2.distro());
            Ros2SimRobot robot = Ros2SimRobot.start(server, context, ros2.topics().namespace(),
                    line -> out.println("rtaware-sim: " + line));
            return new Ros2SimServe(robot, "rtaware-sim: ROS 2 robot node " + Ros2SimRobot.NODE_NAME
                    + " in namespace " + ros2.topics().namespace() + ", domain " + ros2.topics().domain() + ", "
                    + ros2.distro().cliName() + " conventions, " + reached
                    + " (topics scan, odom, ground_truth, cmd_vel)");
        } catch (ZenohException e) {
            throw new IOException("the simulator's ROS 2 side: " + e.getMessage(), e);
        }
    }

    /** @return the line {@code rtaware sim} prints once the robot is served */
    public String startLine() {
        return line;
    }

    /** Stops the robot's node and closes its ROS 2 context. */
    @Override
    public void close() throws IOException {
        try {
            robot.close();
        } catch (ZenohException e) {
            throw new IOException("closing the simulator's ROS 2 side: " + e.getMessage(), e);
        }
    }
}
