package io.rtaware.app.ros2;

import io.rtaware.core.monitor.Monitor;
import io.rtaware.ros2.export.ExportedKey;
import io.rtaware.ros2.export.MonitorExporter;
import io.rtaware.ros2.graph.DdsSettings;
import io.rtaware.ros2.graph.Ros2Context;
import io.rtaware.ros2.graph.Ros2Distro;
import io.rtaware.ros2msg.RobotTopics;
import io.rtaware.zenoh.ZenohException;
import io.rtaware.ros2msg.value.PlanarTransform;
import java.io.PrintStream;
import java.util.ArrayList;
import java.util.List;

/**
 * What {@code --export} asked for. Immutable.
 *
 * @param router the router to connect to, or null
 * @param listen where to listen, or null for a free loopback port
 * @param distro the ROS 2 distribution whose rmw_zenoh conventions to follow
 * @param dds the DDS domain and reach with {@code --dds} (then {@code router} and {@code listen}
 *     are null), or null for rmw_zenoh
 */
public record ExportOptions(String router, String listen, Ros2Distro distro, DdsSettings dds) {

    /** Key period of the exporter: keys are looked at ten times a second. */
    private static final long KEY_PERIOD_MS = 100;

    /**
     * Opens the export session and starts the exporter; prints where it listens.
     *
     * @param monitor the monitor to export
     * @param keys the keys with a ROS 2 type
     * @param staticTransforms what {@code /tf_static} carries (none: no such topic)
     * @param err where the one line goes
     * @return the running exporter
     * @throws io.rtaware.app.UserError if the router cannot be reached or the endpoint bound
     */
    public MonitorExporter start(Monitor monitor, List<ExportedKey<?>> keys, List<PlanarTransform> staticTransforms,
                                 PrintStream err) {
        String at = listen != null ? listen : Ros2Wiring.freeLoopbackEndpoint();
        List<String> connect = router == null ? List.of() : List.of(router);
        Ros2Context context = dds != null ? Ros2Wiring.openDds(dds) : Ros2Wiring.open(connect, List.of(at), 0, distro);
        try {
            MonitorExporter exporter = MonitorExporter.start(monitor, context, keys, staticTransforms, KEY_PERIOD_MS);
            List<String> topics = new ArrayList<>(exporter.topics().values().stream().sorted().toList());
            if (keys.stream().anyMatch(k -> k.transformChild() != null)) {
                topics.add(RobotTopics.TF);
            }
            if (!staticTransforms.isEmpty()) {
                topics.add(RobotTopics.TF_STATIC);
            }
            String where = dds != null ? dds.describe() : "Zenoh on " + at + (router == null ? "" : " via " + router);
            err.println("rtaware export: ROS 2 over " + where
                    + " (" + distro.cliName() + " conventions): "
                    + MonitorExporter.DIAGNOSTICS + ", " + MonitorExporter.STATISTICS + (topics.isEmpty()
                            ? " (no key of this run has a ROS 2 type: each key's health is a status there)"
                            : " and " + String.join(", ", topics)));
            return exporter;
        } catch (ZenohException e) {
            throw new io.rtaware.app.UserError("cannot start the export: " + e.getMessage());
        }
    }

    /**
     * Stops an exporter, if any, without failing the command that ends.
     *
     * @param exporter the exporter or null
     * @param err where a failure is reported in one line
     */
    public static void stop(MonitorExporter exporter, PrintStream err) {
        if (exporter == null) {
            return;
        }
        if (exporter.failure() != null) {
            err.println("rtaware export: stopped early: " + exporter.failure());
        }
        try {
            exporter.close();
        } catch (ZenohException e) {
            err.println("rtaware export: closing: " + e.getMessage());
        }
        if (exporter.statisticsLost() > 0) {
            err.println("rtaware export: " + MonitorExporter.STATISTICS + " left out " + exporter.statisticsLost()
                    + " cycle and commit records (the exporter's thread fell behind the tasks)");
        }
    }
}
