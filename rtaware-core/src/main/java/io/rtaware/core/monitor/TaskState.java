package io.rtaware.core.monitor;

/** The lifecycle of a task under the monitor (the paper's Fig. 1, with its failure exits). */
public enum TaskState {
    /** Declared its data; waiting for the first release. */
    INITIALIZED,
    /** Being released. */
    RUNNING,
    /** Stopped releasing because of an error and the DISABLE_TASK policy. */
    DISABLED,
    /** A once-task that has run, or a task whose thread ended. */
    FINISHED,
    /** Terminated: its thread has stopped and {@code terminate()} was called. */
    TERMINATED
}
