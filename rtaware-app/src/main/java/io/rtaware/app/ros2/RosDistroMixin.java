package io.rtaware.app.ros2;

import io.rtaware.app.UserError;
import io.rtaware.ros2.graph.Ros2Distro;
import picocli.CommandLine.Option;

/**
 * {@code --ros-distro}: the ROS 2 distribution whose rmw_zenoh conventions {@code --ros2} and
 * {@code --export} follow (one option per command, shared by both).
 */
public final class RosDistroMixin {

    @Option(names = "--ros-distro", paramLabel = "humble|jazzy|kilted|rolling",
            description = "Follow the rmw_zenoh conventions of this ROS 2 distribution (with --ros2 or --export; "
                    + "default: kilted, the newest released; humble writes TypeHashNotSupported for type hashes).")
    String name;

    /**
     * @param used whether an option that talks ROS 2 ({@code --ros2}, {@code --export}) was given
     * @param needs those options' names, for the message
     * @return the distribution named, or {@link Ros2Distro#newest()} when none was
     * @throws UserError for an unknown name, or a name without {@code needs}
     */
    public Ros2Distro distro(boolean used, String needs) {
        if (name == null) {
            return Ros2Distro.newest();
        }
        if (!used) {
            throw new UserError("--ros-distro needs " + needs);
        }
        try {
            return Ros2Distro.parse(name);
        } catch (IllegalArgumentException e) {
            throw new UserError("--ros-distro: " + e.getMessage());
        }
    }
}
