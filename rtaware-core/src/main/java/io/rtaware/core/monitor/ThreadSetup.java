package io.rtaware.core.monitor;

/**
 * A hook called on each task thread of the threaded executor when it starts, before the task's
 * first release: the place to set a real-time scheduling policy, CPU affinity or timer slack
 * for that thread (see the {@code rtaware-rt} module's {@code io.rtaware.rt.RealtimeThreads}). Not called by the step executor.
 *
 * <p>Implementations are called concurrently from every task thread and must be thread-safe.
 * An exception is reported on stderr and the task runs on.
 */
@FunctionalInterface
public interface ThreadSetup {

    /**
     * @param task the task whose thread this is (the calling thread)
     * @param rmRank the task's rate-monotonic rank: 0 for the shortest period; periodic tasks
     *     by period (ties in registration order), then the tasks without a period
     * @param taskCount the number of tasks
     */
    void onTaskThreadStart(TaskInfo task, int rmRank, int taskCount);
}
