package io.rtaware.app.ros2;

import io.rtaware.app.UserError;
import io.rtaware.ros2.graph.Ros2Distro;
import io.rtaware.ros2.task.Ros2Topics;
import io.rtaware.ros2.graph.DdsSettings;
import java.util.Optional;
import picocli.CommandLine.Option;

/** The ROS 2 options of {@code sim} (and their validation). */
public final class Ros2SimMixin {

    @Option(names = "--ros2",
            description = "Also serve the world as a ROS 2 robot over Zenoh: scan, odom, ground_truth, cmd_vel.")
    boolean enabled;

    @Option(names = "--zenoh", paramLabel = "tcp/HOST:PORT",
            description = "Zenoh router (rmw_zenohd) to connect to (with --ros2).")
    String zenoh;

    @Option(names = "--listen", paramLabel = "tcp/ADDR:PORT",
            description = "Where the ROS 2 robot's Zenoh session listens (with --ros2; default: a free loopback port).")
    String listen;

    @Option(names = "--domain", defaultValue = "${env:ROS_DOMAIN_ID:-0}", paramLabel = "N",
            description = "ROS domain id (with --ros2; default: ROS_DOMAIN_ID, else 0).")
    int domain;

    @Option(names = "--namespace", defaultValue = "/", paramLabel = "NS",
            description = "The robot's namespace (with --ros2; default: ${DEFAULT-VALUE}).")
    String namespace;

    /** @return true if {@code --ros2} was given (before its options are checked) */
    public boolean requested() {
        return enabled;
    }

    /**
     * @param distro the distribution whose rmw_zenoh conventions to follow
     * @param dds the settings of {@code --dds}, when given ({@link DdsMixin})
     * @return the ROS 2 options when {@code --ros2} was given
     * @throws UserError for a malformed endpoint, namespace or domain, for ROS 2 options without
     *     {@code --ros2}, or when the native Zenoh layer is missing
     */
    public Optional<Ros2Options> options(Ros2Distro distro, Optional<DdsSettings> dds) {
        if (!enabled) {
            if (zenoh != null || listen != null) {
                throw new UserError((zenoh != null ? "--zenoh" : "--listen") + " needs --ros2");
            }
            return Optional.empty();
        }
        if ((zenoh != null || listen != null) && dds.isPresent()) {
            throw new UserError((zenoh != null ? "--zenoh" : "--listen") + " and --dds exclude each other: over DDS "
                    + "the robot is found on --domain " + domain);
        }
        String router = zenoh == null ? null : Ros2Wiring.endpoint(zenoh, "--zenoh", false);
        String at = listen == null ? null : Ros2Wiring.endpoint(listen, "--listen", true);
        Ros2Topics topics;
        try {
            topics = new Ros2Topics(domain, namespace, "scan", "odom", "cmd_vel");
        } catch (IllegalArgumentException e) {
            throw new UserError(e.getMessage());
        }
        Ros2Wiring.requireNativeZenoh();
        return Optional.of(new Ros2Options(router, at, topics, distro, dds.orElse(null)));
    }

    /** @return the {@code --domain} given (or its default), unchecked */
    public int domain() {
        return domain;
    }
}
