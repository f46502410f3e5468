package io.rtaware.app.ros2;

import io.rtaware.app.UserError;
import io.rtaware.ros2.graph.Ros2Distro;
import io.rtaware.ros2.task.Ros2Topics;
import io.rtaware.ros2.graph.DdsSettings;
import java.util.Optional;
import picocli.CommandLine.Option;

/** The ROS 2 options of {@code run} (and their validation). */
public final class Ros2RunMixin {

    @Option(names = "--ros2",
            description = "Drive a ROS 2 robot over Zenoh (rmw_zenoh conventions) instead of a Player server; "
                    + "without --zenoh, the built-in simulator serves as the ROS 2 robot in this process.")
    boolean enabled;

    @Option(names = "--zenoh", paramLabel = "tcp/HOST:PORT",
            description = "Zenoh router (rmw_zenohd) or peer to connect to (with --ros2).")
    String zenoh;

    @Option(names = "--domain", defaultValue = "${env:ROS_DOMAIN_ID:-0}", paramLabel = "N",
            description = "ROS domain id (with --ros2; default: ROS_DOMAIN_ID, else 0).")
    int domain;

    @Option(names = "--namespace", defaultValue = "/", paramLabel = "NS",
            description = "The robot's namespace, e.g. /robot1 (with --ros2; default: ${DEFAULT-VALUE}).")
    String namespace;

    @Option(names = "--scan", defaultValue = "scan", paramLabel = "TOPIC",
            description = "LaserScan topic; relative names are under --namespace (default: ${DEFAULT-VALUE}).")
    String scan;

    @Option(names = "--odom", defaultValue = "odom", paramLabel = "TOPIC",
            description = "Odometry topic (default: ${DEFAULT-VALUE}).")
    String odom;

    @Option(names = "--cmd-vel", defaultValue = "cmd_vel", paramLabel = "TOPIC",
            description = "Twist topic the robot obeys (default: ${DEFAULT-VALUE}).")
    String cmdVel;

    /** @return true if {@code --ros2} was given (nothing is checked) */
    public boolean requested() {
        return enabled;
    }

    /**
     * @param distro the distribution whose rmw_zenoh conventions to follow
     * @param dds the settings of {@code --dds}, when given ({@link DdsMixin})
     * @return the ROS 2 options when {@code --ros2} was given
     * @throws UserError for a malformed endpoint, name or domain, for ROS 2 options without
     *     {@code --ros2}, or when the native Zenoh layer is missing
     */
    public Optional<Ros2Options> options(Ros2Distro distro, Optional<DdsSettings> dds) {
        if (!enabled) {
            if (zenoh != null) {
                throw new UserError("--zenoh needs --ros2");
            }
            return Optional.empty();
        }
        if (zenoh != null && dds.isPresent()) {
            throw new UserError("--zenoh and --dds exclude each other: over DDS the robot is found on --domain " + domain);
        }
        String router = zenoh == null ? null : Ros2Wiring.endpoint(zenoh, "--zenoh", false);
        Ros2Topics topics;
        try {
            topics = new Ros2Topics(domain, namespace, scan, odom, cmdVel);
        } catch (IllegalArgumentException e) {
            throw new UserError(e.getMessage());
        }
        Ros2Wiring.requireNativeZenoh();
        return Optional.of(new Ros2Options(router, null, topics, distro, dds.orElse(null)));
    }

    /** @return the {@code --domain} given (or its default), unchecked */
    public int domain() {
        return domain;
    }
}
