package io.rtaware.core.task;

/**
 * What the monitor does when a task's cycle throws. The exception is always caught, counted
 * and reported with the task's name first; nothing dies silently.
 */
public enum ErrorPolicy {
    /** Keep releasing the task; its outputs of the failed cycle are not committed. */
    CONTINUE,
    /** Stop releasing this task; the others go on and its keys go stale. */
    DISABLE_TASK,
    /** Stop every task and terminate the monitor. */
    STOP_ALL
}
