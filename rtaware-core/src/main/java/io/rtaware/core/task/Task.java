package io.rtaware.core.task;

/**
 * A behavior: the unit the monitor schedules. A task goes through the paper's three states:
 * <ol>
 *   <li><b>Initialization</b>: {@link #initialize(TaskSetup)} declares the keys it produces and
 *   consumes and allocates everything it will need; the monitor verifies the whole data graph
 *   before the first release.</li>
 *   <li><b>Execution</b>: {@link #execute(long)} runs once per release. The framework has just
 *   copied the task's inputs into its buffers; outputs it publishes are committed when the
 *   cycle returns.</li>
 *   <li><b>Termination</b>: {@link #terminate()} releases resources once the task's cycles have
 *   stopped.</li>
 * </ol>
 * A task does not know which thread or executor runs it. Its name and schedule are given when
 * it is registered with the monitor. A task is called by one thread at a time.
 */
public interface Task {

    /**
     * Declares produced and consumed keys and allocates the task's working memory.
     *
     * @param setup the declarations interface, valid only during this call
     * @throws Exception if the task cannot be initialized; the monitor reports it and does not
     *     start
     */
    void initialize(TaskSetup setup) throws Exception;

    /**
     * One cycle of work.
     *
     * @param nowNs world time at the start of the cycle (read once by the framework)
     * @throws Exception any failure; the monitor catches it, counts it and applies the task's
     *     {@link ErrorPolicy}
     */
    void execute(long nowNs) throws Exception;

    /**
     * Whether a cycle may block the calling thread waiting for something outside the process (a
     * socket read, a device): such a task gets a thread of its own under every executor, so it
     * never holds up a pooled worker that other tasks are due on. The default is false: a cycle
     * computes and returns.
     *
     * @return true if {@link #execute(long)} can block
     */
    default boolean blocks() {
        return false;
    }

    /**
     * Whether the monitor must stop this task before the others: a task that commands actuators
     * (it sends a robot its velocity) returns true, and its {@link #terminate()} puts them in a
     * safe state (a zero velocity). On stop, no task is released again; then the threads of the
     * tasks that stop first are waited for and those tasks terminated, in registration order,
     * while the other tasks may still be finishing their last cycle (a planner in the middle of a
     * long search holds up no stop of the robot); the others are terminated once every thread
     * has returned. The default is false.
     *
     * @return true to be stopped and terminated before the other tasks
     */
    default boolean stopsFirst() {
        return false;
    }

    /**
     * Releases what the task holds. Called once, after the task's cycles have stopped: for the
     * tasks that {@link #stopsFirst() stop first} as soon as their own threads have returned, for
     * the others once every task thread has; each group in registration order. The default does
     * nothing.
     *
     * @throws Exception if cleaning up fails; reported, never propagated
     */
    default void terminate() throws Exception {
    }
}
