package io.rtaware.bench.compare;

import io.rtaware.bench.load.BenchSpec;
import java.util.List;

/**
 * One way of running the compared task set for one segment: it starts one thread per task,
 * reports every run to the task's {@link ReleaseStats}, and stops. A new instance (and new
 * threads) is used for every segment. Not thread-safe: the coordinator calls it.
 */
interface SegmentExecutor {

    /** @return the name used in the table and as {@code executor} in the JSON */
    String name();

    /**
     * Builds what the executor needs before its segment's clock starts (objects, not threads), so
     * building a large task set is not charged to the executor's lateness. Default: nothing.
     *
     * @param specs the tasks
     * @param stats one per task, in the same order
     */
    default void prepare(List<BenchSpec> specs, List<ReleaseStats> stats) {
    }

    /**
     * Starts the tasks; the first release is now.
     *
     * @param specs the tasks
     * @param stats one per task, in the same order, already reset for this segment
     */
    void start(List<BenchSpec> specs, List<ReleaseStats> stats);

    /** @return ids of the executor's own threads besides the task threads (e.g. a watchdog) */
    long[] helperThreadIds();

    /** Stops releasing, waits for the task threads to return. */
    void stop() throws InterruptedException;
}
