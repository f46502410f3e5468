package io.rtaware.app.ros2;

import io.rtaware.app.UserError;
import io.rtaware.robotrun.Ros2Link;
import io.rtaware.ros2.graph.DdsSettings;
import io.rtaware.ros2.graph.Ros2Context;
import io.rtaware.ros2.graph.Ros2Distro;
import io.rtaware.ros2.graph.Ros2Transport;
import io.rtaware.ros2.task.Ros2DataTask;
import io.rtaware.sim.ros2.Ros2SimRobot;
import io.rtaware.sim.server.PlayerSimServer;
import io.rtaware.zenoh.ZenohConfig;
import io.rtaware.zenoh.ZenohException;
import io.rtaware.zenoh.ZenohLibrary;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.util.List;

/**
 * Opening Zenoh sessions, and the ROS 2 side of a run, for the command line, with user errors for
 * what the user can fix. Stateless.
 */
public final class Ros2Wiring {

    private Ros2Wiring() {
    }

    /**
     * @throws UserError if the native Zenoh layer is missing, saying how to enable it
     */
    public static void requireNativeZenoh() {
        String reason = ZenohLibrary.unavailableReason();
        if (reason != null) {
            throw new UserError("--ros2 is not available: " + reason);
        }
    }

    /**
     * @param text an endpoint from the command line
     * @param option its option name
     * @param listen whether port 0 is allowed
     * @return the endpoint
     * @throws UserError if malformed
     */
    public static String endpoint(String text, String option, boolean listen) {
        try {
            return ZenohConfig.checkEndpoint(text, listen);
        } catch (IllegalArgumentException e) {
            throw new UserError(option + ": " + e.getMessage());
        }
    }

    /**
     * Opens a peer session (multicast scouting off) and its context.
     *
     * @param connect where to connect (empty for nowhere)
     * @param listen where to listen
     * @param domain the ROS domain
     * @param distro the distribution whose rmw_zenoh conventions the context follows
     * @return the context
     * @throws UserError if the router cannot be reached or the listen endpoint cannot be bound
     */
    public static Ros2Context open(List<String> connect, List<String> listen, int domain, Ros2Distro distro) {
        requireNativeZenoh();
        ZenohConfig config = ZenohConfig.loopbackPeer().withConnect(connect).withListen(listen);
        try {
            return Ros2Context.open(config, domain, distro);
        } catch (ZenohException e) {
            String where = connect.isEmpty() ? "listen on " + String.join(", ", listen)
                    : "reach the Zenoh router at " + String.join(", ", connect);
            throw new UserError("cannot " + where + ": " + e.getMessage().lines().findFirst().orElse(""));
        }
    }

    /** How long a DDS bridge may take to start before the command gives up: 10 s. */
    private static final long DDS_START_TIMEOUT_MS = 10_000;

    /**
     * Starts the ROS 2 DDS bridge and opens a context on it.
     *
     * @param dds the DDS domain and reach
     * @return the context (owning the bridge)
     * @throws UserError if the bridge cannot start
     */
    public static Ros2Context openDds(DdsSettings dds) {
        try {
            return Ros2Context.openDds(dds, DDS_START_TIMEOUT_MS);
        } catch (ZenohException e) {
            throw new UserError("--dds: cannot join " + dds.describe() + ": " + e.getMessage().lines().findFirst().orElse(""));
        }
    }

    /**
     * Opens the ROS 2 side of one {@code run --ros2}: the controller's Zenoh context and data task
     * and, without {@code --zenoh} or {@code --dds}, the built-in simulator served as a ROS 2 robot
     * in the same process (its own session listening on a free loopback port, the controller's
     * session connecting to it).
     *
     * @param options what {@code --ros2} asked for
     * @param server the built-in simulator, or null when the robot is reached through a router or over DDS
     * @return the link
     * @throws UserError if a router cannot be reached or the DDS bridge cannot start
     */
    public static Ros2Link link(Ros2Options options, PlayerSimServer server) {
        Ros2Transport transport = options.dds() != null ? Ros2Transport.DDS : Ros2Transport.RMW_ZENOH;
        if (options.dds() != null) {
            return new Ros2Link(Ros2DataTask.withDefaults(openDds(options.dds()), options.topics()), null,
                    "ROS 2 robot over " + options.dds().describe(), transport, options.distro());
        }
        Ros2SimRobot robot = null;
        List<String> connect;
        if (options.router() == null) {
            String endpoint = freeLoopbackEndpoint();
            Ros2Context simContext = open(List.of(), List.of(endpoint), options.topics().domain(), options.distro());
            try {
                // its notices reach the run's summary and report through Ros2Link.notices()
                robot = Ros2SimRobot.start(server, simContext, options.topics().namespace(), line -> { });
            } catch (ZenohException e) {
                throw new IllegalStateException("the simulator's ROS 2 side did not start: " + e.getMessage(), e);
            }
            connect = List.of(endpoint);
        } else {
            connect = List.of(options.router());
        }
        try {
            Ros2Context context = open(connect, List.of(ZenohConfig.LOOPBACK_ANY_PORT), options.topics().domain(),
                    options.distro());
            return new Ros2Link(Ros2DataTask.withDefaults(context, options.topics()), robot,
                    options.router() == null ? "built-in simulator as a ROS 2 robot over Zenoh on loopback"
                            : "ROS 2 robot through Zenoh at " + options.router(), transport, options.distro());
        } catch (RuntimeException e) {
            if (robot != null) {
                try {
                    robot.close();
                } catch (ZenohException closing) {
                    e.addSuppressed(closing);
                }
            }
            throw e;
        }
    }

    /** @return a loopback endpoint on a port that was free a moment ago */
    public static String freeLoopbackEndpoint() {
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            return "tcp/127.0.0.1:" + s.getLocalPort();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
