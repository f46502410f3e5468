package io.rtaware.core.testing;

import io.rtaware.core.monitor.TaskInfo;
import io.rtaware.core.task.Schedule;
import java.util.List;

/**
 * A task as a monitor describes it, fixed, for tests of listeners and recorders that need a
 * {@link TaskInfo} without a monitor.
 *
 * @param name the task's name
 * @param index its index
 * @param schedule its schedule
 * @param inputKeys the keys it reads, in order
 */
public record FixedTaskInfo(String name, int index, Schedule schedule, List<String> inputKeys) implements TaskInfo {

    /**
     * @param name the task's name
     * @param index its index
     * @param schedule its schedule
     * @param inputKeys the keys it reads, in order (copied)
     */
    public FixedTaskInfo {
        inputKeys = List.copyOf(inputKeys);
    }
}
