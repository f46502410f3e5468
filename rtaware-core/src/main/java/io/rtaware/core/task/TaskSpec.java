package io.rtaware.core.task;

import java.util.Objects;

/**
 * A task registered with the monitor: its name, schedule, error policy and the behavior.
 *
 * @param name unique name, used in every report line
 * @param schedule when it runs
 * @param errorPolicy what an exception in a cycle does
 * @param task the behavior
 */
public record TaskSpec(String name, Schedule schedule, ErrorPolicy errorPolicy, Task task) {

    /**
     * Checks for nulls; values are validated by the monitor, all at once.
     *
     * @param name unique name, used in every report line
     * @param schedule when it runs
     * @param errorPolicy what an exception in a cycle does
     * @param task the behavior
     */
    public TaskSpec {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(schedule, "schedule");
        Objects.requireNonNull(errorPolicy, "errorPolicy");
        Objects.requireNonNull(task, "task");
    }
}
