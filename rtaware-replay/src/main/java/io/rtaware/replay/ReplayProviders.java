package io.rtaware.replay;

import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.TaskSpec;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.ServiceLoader;

/**
 * The {@link ReplayableController} providers visible to a class loader, and the controller of a
 * recording among them. Immutable after construction.
 */
public final class ReplayProviders {

    private final List<ReplayableController> providers;

    private ReplayProviders(List<ReplayableController> providers) {
        this.providers = List.copyOf(providers);
    }

    /**
     * Loads every provider registered in {@code META-INF/services} and visible to the loader.
     *
     * @param loader the class loader to search (e.g. a {@link java.net.URLClassLoader} over a user's classes)
     * @return the providers
     * @throws java.util.ServiceConfigurationError if a registered provider cannot be loaded
     */
    public static ReplayProviders load(ClassLoader loader) {
        List<ReplayableController> found = new ArrayList<>();
        ServiceLoader.load(ReplayableController.class, loader).forEach(found::add);
        return new ReplayProviders(found);
    }

    /** @return the ids of the providers found, in the order found */
    public List<String> ids() {
        return providers.stream().map(ReplayableController::id).toList();
    }

    /**
     * Finds the controller of a recording.
     *
     * @param runMetadata the recording's {@code rtaware.run} entries
     * @return its controller with its configuration
     * @throws IllegalArgumentException naming the provider id if no provider has it, or saying
     *     that the recording names none
     */
    public RecordedController controllerOf(Map<String, String> runMetadata) {
        String id = runMetadata.get(ReplayableController.CONTROLLER);
        if (id == null) {
            for (ReplayableController p : providers) {
                if (p.recognizesUnnamed(runMetadata)) {
                    return new RecordedController(p, runMetadata);
                }
            }
            throw new IllegalArgumentException("its rtaware.run metadata names no controller ('"
                    + ReplayableController.CONTROLLER + "'): it was not recorded with ReplayableController.describe");
        }
        for (ReplayableController p : providers) {
            if (p.id().equals(id)) {
                Map<String, String> configuration = new LinkedHashMap<>();
                runMetadata.forEach((name, value) -> {
                    if (name.startsWith(ReplayableController.CONFIGURATION_PREFIX)) {
                        configuration.put(name.substring(ReplayableController.CONFIGURATION_PREFIX.length()), value);
                    }
                });
                return new RecordedController(p, Map.copyOf(configuration));
            }
        }
        throw new IllegalArgumentException("its controller '" + id + "' has no replay provider here: pass the"
                + " controller's classes with --classpath (providers found: " + String.join(", ", ids()) + ")");
    }

    /**
     * A recording's controller: its provider and the configuration recorded for it.
     *
     * @param provider the provider
     * @param configuration its recorded configuration
     */
    public record RecordedController(ReplayableController provider, Map<String, String> configuration) {

        /**
         * @param periodsNs period in ns of each task to change; empty for the recorded periods
         * @return a fresh set of the controller's tasks
         * @throws IllegalArgumentException as {@link ReplayableController#tasks}
         */
        public List<TaskSpec> tasks(Map<String, Long> periodsNs) {
            return provider.tasks(configuration, periodsNs);
        }

        /**
         * @return the recorded period in ns of each periodic task, by name, in the controller's order
         * @throws IllegalArgumentException as {@link ReplayableController#tasks}
         */
        public Map<String, Long> recordedPeriodsNs() {
            return periodsNs(tasks(Map.of()));
        }
    }

    /**
     * @param tasks a controller's tasks
     * @return the period in ns of each periodic task, by name, in the tasks' order
     */
    public static Map<String, Long> periodsNs(List<TaskSpec> tasks) {
        Map<String, Long> periods = new LinkedHashMap<>();
        for (TaskSpec spec : tasks) {
            if (spec.schedule() instanceof Schedule.Periodic p) {
                periods.put(spec.name(), p.periodNs());
            }
        }
        return periods;
    }
}
