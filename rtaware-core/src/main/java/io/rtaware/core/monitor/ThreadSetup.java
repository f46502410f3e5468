package io.rtaware.core.monitor;

/**
 * A hook called on each thread that runs cycles when it starts, before the first release: each
 * task thread of the threaded executor (and the pooled executor's tasks with a thread of their
 * own), and each worker of the pooled executor; and on each executor's watchdog, the thread that
 * reports misses at their deadlines. The place to set a real-time scheduling policy,
 * CPU affinity or timer slack for that thread (see the {@code rtaware-rt} module's {@code io.rtaware.rt.RealtimeThreads}). Not called by the step executor.
 *
 * <p>Implementations are called concurrently from every task thread and must be thread-safe.
 * An exception is reported on stderr and the task runs on.
 */
public interface ThreadSetup {

    /**
     * @param task the task whose thread this is (the calling thread)
     * @param rmRank the task's rate-monotonic rank: 0 for the shortest period; periodic tasks
     *     by period (ties in registration order), then the tasks without a period
     * @param taskCount the number of tasks
     */
    void onTaskThreadStart(TaskInfo task, int rmRank, int taskCount);

    /**
     * Called on each worker thread of the pooled executor (the calling thread) before it takes
     * its first release. A worker runs releases of every pooled task, so it is given the rank of
     * the most urgent of them.
     *
     * @param worker the worker's number, from 0
     * @param rmRank the rate-monotonic rank (as in {@link #onTaskThreadStart}) of the
     *     shortest-period task the pool runs
     * @param taskCount the number of tasks
     */
    void onPoolWorkerStart(int worker, int rmRank, int taskCount);

    /**
     * Called on the watchdog thread of the threaded or pooled executor (the calling thread)
     * before its first look at the tasks. The watchdog wakes at the deadlines of running cycles
     * and reports a cycle still running past its deadline at that moment; it runs for a few
     * microseconds each time. Left at normal priority beside real-time task threads that keep
     * every CPU busy, it cannot run then, and a miss is reported only when the cycle returns: a
     * real-time setup gives it a priority above every task's. Does nothing unless implemented.
     *
     * @param taskCount the number of tasks
     */
    default void onWatchdogStart(int taskCount) {
    }
}
