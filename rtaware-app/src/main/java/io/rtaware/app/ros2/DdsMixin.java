package io.rtaware.app.ros2;

import io.rtaware.app.UserError;
import io.rtaware.ros2.graph.DdsSettings;
import io.rtaware.ros2.graph.Ros2Distro;
import io.rtaware.zenoh.DdsBridge;
import io.rtaware.zenoh.DdsBridgeConfig;
import java.util.Optional;
import picocli.CommandLine.Option;

/**
 * {@code --dds} and {@code --dds-interface}: reach ROS 2 over DDS, through the ROS 2 DDS bridge
 * (a process the command starts), for everything ROS 2 in a command ({@code --ros2}, {@code --export}).
 */
public final class DdsMixin {

    @Option(names = "--dds",
            description = "Speak DDS (RTPS), the default ROS 2 middleware, instead of rmw_zenoh (with --ros2 or --export): "
                    + "Zenoh's ROS 2 DDS bridge (zenoh-plugin-ros2dds on Eclipse Cyclone DDS) runs in a process of its own "
                    + "on --domain; topics are rt/<name> as ROS 2 writes them. DDS stays on the loopback interface, its "
                    + "sockets bound to 127.0.0.1, with multicast off unless --dds-interface names another "
                    + "(CYCLONEDDS_URI, when set, replaces both).")
    boolean enabled;

    @Option(names = "--dds-interface", paramLabel = "NAME",
            description = "The network interface DDS uses (with --dds; default: lo, this machine only). Naming the robot's "
                    + "network (e.g. eth0) opens DDS to it, with multicast discovery as a stock ROS 2 node does.")
    String networkInterface;

    /** @return true if {@code --dds} was given (nothing is checked) */
    public boolean requested() {
        return enabled;
    }

    /**
     * @param used whether an option that talks ROS 2 was given
     * @param needs those options' names, for the message
     * @param domain the DDS domain (the command's {@code --domain}, or {@code ROS_DOMAIN_ID})
     * @param distro the distribution the bridge behaves as
     * @return the DDS settings when {@code --dds} was given
     * @throws UserError for DDS options without {@code --dds} or without {@code needs}, a domain
     *     outside 0..232, a malformed interface name or one this machine does not have (or has
     *     without an IPv4 address), an unreadable {@code CYCLONEDDS_URI}, or a build without the
     *     bridge
     */
    public Optional<DdsSettings> settings(boolean used, String needs, int domain, Ros2Distro distro) {
        if (!enabled) {
            if (networkInterface != null) {
                throw new UserError("--dds-interface needs --dds");
            }
            return Optional.empty();
        }
        if (!used) {
            throw new UserError("--dds needs " + needs);
        }
        DdsSettings settings;
        try {
            settings = new DdsSettings(domain, distro, networkInterface == null ? DdsSettings.LOOPBACK : networkInterface,
                    System.getenv("CYCLONEDDS_URI"));
        } catch (IllegalArgumentException e) {
            throw new UserError("--dds: " + e.getMessage());
        }
        if (settings.bindInterface() != null) {
            try {
                DdsBridgeConfig.interfaceAddress(settings.bindInterface());
            } catch (IllegalArgumentException e) {
                throw new UserError("--dds-interface: " + e.getMessage());
            }
        }
        String reason = DdsBridge.unavailableReason();
        if (reason != null) {
            throw new UserError("--dds is not available: " + reason);
        }
        return Optional.of(settings);
    }
}
