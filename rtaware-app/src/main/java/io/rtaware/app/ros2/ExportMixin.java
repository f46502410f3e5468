package io.rtaware.app.ros2;

import io.rtaware.app.UserError;
import io.rtaware.ros2.graph.DdsSettings;
import io.rtaware.ros2.graph.Ros2Distro;
import java.util.Optional;
import picocli.CommandLine.Option;

/** The {@code --export} options of {@code run} and {@code bench}. */
public final class ExportMixin {

    @Option(names = "--export",
            description = "Publish every key with a ROS 2 type under /rtaware/... and each task's health once a second "
                    + "as diagnostic_msgs/msg/DiagnosticArray on /diagnostics, over Zenoh (rmw_zenoh conventions).")
    boolean enabled;

    @Option(names = "--export-zenoh", paramLabel = "tcp/HOST:PORT",
            description = "Zenoh router to export through (with --export; default: none, peers connect to --export-listen).")
    String router;

    @Option(names = "--export-listen", paramLabel = "tcp/ADDR:PORT",
            description = "Where the export session listens (with --export; default: a free loopback port).")
    String listen;

    /** @return true if {@code --export} was given (nothing is checked) */
    public boolean requested() {
        return enabled;
    }

    /**
     * @param distro the distribution whose rmw_zenoh conventions to follow
     * @param dds the settings of {@code --dds}, when given ({@link DdsMixin})
     * @return the export options when {@code --export} was given
     * @throws UserError for a malformed endpoint, export options without {@code --export}, or a
     *     missing native Zenoh layer
     */
    public Optional<ExportOptions> options(Ros2Distro distro, Optional<DdsSettings> dds) {
        if (!enabled) {
            if (router != null || listen != null) {
                throw new UserError((router != null ? "--export-zenoh" : "--export-listen") + " needs --export");
            }
            return Optional.empty();
        }
        if ((router != null || listen != null) && dds.isPresent()) {
            throw new UserError((router != null ? "--export-zenoh" : "--export-listen") + " and --dds exclude each other");
        }
        String at = router == null ? null : Ros2Wiring.endpoint(router, "--export-zenoh", false);
        String on = listen == null ? null : Ros2Wiring.endpoint(listen, "--export-listen", true);
        Ros2Wiring.requireNativeZenoh();
        return Optional.of(new ExportOptions(at, on, distro, dds.orElse(null)));
    }
}
