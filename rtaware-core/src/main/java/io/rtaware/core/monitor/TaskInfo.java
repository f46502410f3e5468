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
}
