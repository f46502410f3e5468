package io.rtaware.app.ros2;

import io.rtaware.ros2.graph.DdsSettings;
import io.rtaware.ros2.graph.Ros2Distro;
import io.rtaware.ros2.task.Ros2Topics;
import java.util.Optional;

/**
 * What {@code --ros2} asked for, validated by the mixins. Immutable.
 *
 * @param router the Zenoh endpoint to connect to ({@code tcp/HOST:PORT}), or null for the
 *     built-in simulator in the same process
 * @param listen where the simulator's session listens, or null for a free loopback port
 * @param topics domain, namespace and topic names
 * @param distro the ROS 2 distribution whose rmw_zenoh conventions to follow
 * @param dds the DDS domain and reach with {@code --dds} (then {@code router} and {@code listen}
 *     are null: the robot is found on the domain), or null for rmw_zenoh
 */
public record Ros2Options(String router, String listen, Ros2Topics topics, Ros2Distro distro, DdsSettings dds) {

    /** @return whether the built-in simulator serves as the robot in this process (neither --zenoh nor --dds) */
    public boolean builtInSimulator() {
        return router == null && dds == null;
    }

    /** @return the router endpoint, if one was given */
    public Optional<String> routerEndpoint() {
        return Optional.ofNullable(router);
    }
}
