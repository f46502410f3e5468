package io.rtaware.app.ros2;

import io.rtaware.app.UserError;
import io.rtaware.ros2.graph.DdsSettings;
import io.rtaware.ros2.graph.Ros2Context;
import io.rtaware.ros2.graph.Ros2Distro;
import io.rtaware.zenoh.ZenohConfig;
import io.rtaware.zenoh.ZenohException;
import io.rtaware.zenoh.ZenohLibrary;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.util.List;

/** Opening Zenoh sessions for the command line, with user errors for what the user can fix. Stateless. */
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

    /** @return a loopback endpoint on a port that was free a moment ago */
    public static String freeLoopbackEndpoint() {
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            return "tcp/127.0.0.1:" + s.getLocalPort();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
