package io.rtaware.record.encode;

import io.rtaware.ros2msg.MessageDefinition;
import io.rtaware.ros2msg.Ros2MessageType;
import io.rtaware.ros2msg.TypeDescriptionHash;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;

/**
 * rtaware's own message types, the ROS 2 package {@code rtaware_msgs} (its {@code .msg} files
 * are resources of this module, under {@code rtaware_msgs/}, with a package.xml and
 * CMakeLists.txt so a ROS 2 workspace builds them): schema encoding {@code ros2msg}, message
 * encoding {@code cdr}, so that every MCAP ROS 2 reader, Foxglove and rosbags included, decodes
 * them from the definition in the file with no plug-in. Each type's RIHS01 hash is computed from
 * its definition as rosidl computes it ({@link TypeDescriptionHash}), so recordings declare
 * {@code topic_type_hash} for these channels as for the standard types.
 */
public final class TimingTypes {

    /** Outcome of a cycle that finished by its deadline, read new data and did not throw. */
    public static final String OK = "ok";
    /** Outcome of a cycle that finished after its deadline. */
    public static final String MISS = "miss";
    /** Outcome recorded for releases skipped because the task was still running. */
    public static final String SKIPPED = "skipped";
    /** Outcome of a cycle whose inputs had no new data. */
    public static final String STALE = "stale";
    /** Outcome of a cycle that threw. */
    public static final String ERROR = "error";

    /** One task cycle: {@code /rtaware/timing/<task>}. */
    public static final Ros2MessageType TASK_CYCLE = load("TaskCycle");

    /** One monitor event: {@code /rtaware/events}. */
    public static final Ros2MessageType MONITOR_EVENT = load("MonitorEvent");

    /**
     * One committed value as the JSON of its fields: {@code /rtaware/state/<key>} and
     * {@code /rtaware/data/<key>}.
     */
    public static final Ros2MessageType STATE_JSON = load("StateJson");

    /** The position mediator's decision of one cycle: {@code /rtaware/data/mediator.decision}. */
    public static final Ros2MessageType MEDIATOR_DECISION = load("MediatorDecision");

    /** Where the {@code rtaware_msgs} ROS 2 package (package.xml, msg/) lies on the class path. */
    public static final String PACKAGE_RESOURCE = "/rtaware_msgs/";

    /**
     * @param type a type of {@code rtaware_msgs}
     * @return the type: its definition, read from the package's {@code .msg} file shipped with the
     *     recorder, and its RIHS01 hash
     */
    private static Ros2MessageType load(String type) {
        String resource = PACKAGE_RESOURCE + "msg/" + type + ".msg";
        try (InputStream in = TimingTypes.class.getResourceAsStream(resource)) {
            if (in == null) {
                throw new IllegalStateException("the recorder's class path lacks " + resource);
            }
            MessageDefinition definition = new MessageDefinition("rtaware_msgs/msg/" + type,
                    new String(in.readAllBytes(), StandardCharsets.UTF_8));
            return new Ros2MessageType(definition, TypeDescriptionHash.rihs01(definition));
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read " + resource, e);
        }
    }

    private TimingTypes() {
    }
}
