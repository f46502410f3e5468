package io.rtaware.core.monitor;

/**
 * Which executor {@link Monitor#start()} uses ({@link Monitor.Builder#executor}).
 *
 * <ul>
 *   <li>{@link Threaded}: one platform thread per task, as in the paper. Best up to a few
 *   hundred tasks, and for tasks that need a thread of their own (real-time priorities per
 *   task, affinity).</li>
 *   <li>{@link Pooled}: a few worker threads release the periodic tasks from one timer
 *   structure in deadline order; continuous tasks and tasks that {@link
 *   io.rtaware.core.task.Task#blocks() block} still get a thread of their own. For thousands of
 *   tasks, where a thread each costs more than the work.</li>
 * </ul>
 * Both follow the same rulebook ({@link TaskRuntime}): the same grid, misses, skips and counts.
 */
public sealed interface ExecutorKind permits ExecutorKind.Threaded, ExecutorKind.Pooled {

    /** @return one thread per task (the default) */
    static ExecutorKind threaded() {
        return new Threaded();
    }

    /** @return a pool of one worker per available core, earliest deadline first */
    static ExecutorKind pooled() {
        return new Pooled(Runtime.getRuntime().availableProcessors(), PoolOrder.EARLIEST_DEADLINE_FIRST);
    }

    /**
     * @param workers worker threads, 1 to {@link Pooled#maxWorkers()}
     * @param order which due release a free worker runs first
     * @return a pool
     */
    static ExecutorKind pooled(int workers, PoolOrder order) {
        return new Pooled(workers, order);
    }

    /** One platform thread per task. */
    record Threaded() implements ExecutorKind {
    }

    /**
     * A pool of worker threads for the periodic tasks that do not block.
     *
     * <p>At most {@value #MAX_WORKERS_PER_CORE} workers per available core: the pooled tasks do
     * not block, so no more than one worker per core runs at a time; the others are there so that
     * a release need not wait behind cycles that overrun, and {@value #MAX_WORKERS_PER_CORE} per
     * core covers that many overruns at once on every core. Past that a pool is a thread per task
     * by another name (the threaded executor says so plainly), and thousands of workers end in
     * the operating system's refusal of another thread.
     *
     * @param workers worker threads, 1 to {@link #maxWorkers()}
     * @param order which due release a free worker runs first
     */
    record Pooled(int workers, PoolOrder order) implements ExecutorKind {

        /** Most workers a pool may have per available core. */
        public static final int MAX_WORKERS_PER_CORE = 16;

        /**
         * Checks the values.
         *
         * @param workers worker threads, 1 to {@link #maxWorkers()}
         * @param order which due release a free worker runs first
         */
        public Pooled {
            if (workers < 1) {
                throw new IllegalArgumentException("a pool needs at least 1 worker, got " + workers);
            }
            if (workers > maxWorkers()) {
                throw new IllegalArgumentException("a pool may have at most " + maxWorkers() + " workers ("
                        + MAX_WORKERS_PER_CORE + " per core, " + Runtime.getRuntime().availableProcessors()
                        + " cores), got " + workers);
            }
            java.util.Objects.requireNonNull(order, "order");
        }

        /** @return the most workers a pool may have here: {@value #MAX_WORKERS_PER_CORE} per available core */
        public static int maxWorkers() {
            return MAX_WORKERS_PER_CORE * Runtime.getRuntime().availableProcessors();
        }
    }

    /** Which of the due releases a free pool worker runs first. */
    enum PoolOrder {
        /** The release with the earliest absolute deadline (ties: registration order). */
        EARLIEST_DEADLINE_FIRST,
        /** The task with the shortest period (ties: registration order). */
        RATE_MONOTONIC
    }
}
