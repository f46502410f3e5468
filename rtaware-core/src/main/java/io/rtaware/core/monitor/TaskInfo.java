package io.rtaware.core.monitor;

import io.rtaware.core.task.Schedule;

/**
 * What listeners may know about a task: identity and schedule. Thread-safe.
 */
public interface TaskInfo {

    /** @return the task's unique name */
    String name();

    /** @return dense index from 0 in registration order, usable as an array index */
    int index();

    /** @return the declared schedule */
    Schedule schedule();

    /**
     * @return the names of the keys the task consumes, in the order of the generations in
     *     {@link MonitorListener#onCycleRecord} (empty unless the task is one of a monitor's)
     */
    default java.util.List<String> inputKeys() {
        return java.util.List.of();
    }
}
