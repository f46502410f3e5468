package io.rtaware.replay;

import io.rtaware.core.task.TaskSpec;
import io.rtaware.record.RecordingPlan;
import java.util.List;
import java.util.Map;

/**
 * A controller that can be replayed from its recordings: the service interface through which
 * {@code rtaware replay} (and {@link ReplayProviders}) rebuilds any user's controller. The
 * recorder names the provider and stores the configuration it needs in the recording's
 * {@code rtaware.run} metadata ({@link #describe}); replay finds the provider by that id with
 * {@link java.util.ServiceLoader} and asks it for a fresh set of the controller's tasks.
 *
 * <p>Register an implementation (a public class with a public no-argument constructor) in
 * {@code META-INF/services/io.rtaware.replay.ReplayableController}. Implementations must be
 * thread-safe and stateless: {@link #tasks} is called several times per replay, and every call
 * must return new task instances in their initial state.
 */
public interface ReplayableController {

    /** {@code rtaware.run} metadata entry naming the provider that rebuilds the controller. */
    String CONTROLLER = "controller";
    /** Prefix of the {@code rtaware.run} metadata entries that hold the controller's configuration. */
    String CONFIGURATION_PREFIX = "controller.";

    /**
     * @return the id the recordings name this provider by, e.g. {@code com.example.my-robot}; stable
     *     across versions that can replay the same recordings
     */
    String id();

    /**
     * Builds a fresh set of the controller's tasks as they were recorded, or with other periods
     * (a what-if replay), deriving again whatever the controller derives from its periods.
     *
     * @param configuration the configuration stored with {@link #describe} (without the prefix)
     * @param periodsNs period in ns of each task to change, by task name; empty for the recorded periods
     * @return new task instances, in the controller's order
     * @throws IllegalArgumentException if the configuration is not readable or a period or task name is invalid
     */
    List<TaskSpec> tasks(Map<String, String> configuration, Map<String, Long> periodsNs);

    /**
     * For recordings made before the recorder named a provider: whether this provider recognizes
     * the recording by its metadata. Such a recording's configuration is its whole metadata.
     *
     * @param runMetadata a recording's {@code rtaware.run} entries, without a {@value #CONTROLLER} entry
     * @return true if this provider rebuilds the controller of such a recording
     */
    default boolean recognizesUnnamed(Map<String, String> runMetadata) {
        return false;
    }

    /**
     * Names the provider and stores its configuration in a recording's {@code rtaware.run}
     * metadata, so that the recording can be replayed.
     *
     * @param plan the recording plan of the run
     * @param id the provider's {@link #id()}
     * @param configuration what {@link #tasks} needs to rebuild the controller (names without the prefix)
     * @return the plan
     */
    static RecordingPlan describe(RecordingPlan plan, String id, Map<String, String> configuration) {
        plan.metadata(CONTROLLER, id);
        configuration.forEach((name, value) -> plan.metadata(CONFIGURATION_PREFIX + name, value));
        return plan;
    }
}
