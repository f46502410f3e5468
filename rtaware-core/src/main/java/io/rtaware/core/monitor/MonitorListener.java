package io.rtaware.core.monitor;

/**
 * Receives the monitor's events as they happen. Every method has a no-op default.
 *
 * <p>Methods are called on task threads and on the monitor's watchdog thread, concurrently:
 * implementations must be thread-safe, fast, and must not block or allocate on the common
 * paths ({@link #onCycle}, {@link #onStaleRun}, {@link #onCommit}); hand slow work such as
 * printing to a thread of their own.
 */
public interface MonitorListener {

    /**
     * A release did not finish by its deadline. Reported at the deadline while the task is still
     * running ({@code stillRunning}), at the start of a cycle that started after its deadline
     * (also {@code stillRunning}), or when a late cycle returns if the watchdog had not seen it.
     *
     * @param task the task
     * @param releaseNs scheduled release
     * @param deadlineNs absolute deadline
     * @param detectedNs world time of detection
     * @param stillRunning true if the cycle was still running when detected
     */
    default void onDeadlineMiss(TaskInfo task, long releaseNs, long deadlineNs, long detectedNs,
                                boolean stillRunning) {
    }

    /**
     * Releases were skipped because the task was still running when they came due; each is a miss.
     *
     * @param task the task
     * @param skipped how many releases were skipped
     * @param nowNs world time
     */
    default void onSkippedReleases(TaskInfo task, long skipped, long nowNs) {
    }

    /**
     * The task ran although none of its inputs had new data since its previous cycle.
     *
     * @param task the task
     * @param nowNs cycle start
     */
    default void onStaleRun(TaskInfo task, long nowNs) {
    }

    /**
     * The task read an input older than the maximum age it declared.
     *
     * @param task the task
     * @param key the input's key name
     * @param ageNs the value's age
     * @param maxAgeNs the declared maximum age
     * @param nowNs cycle start
     */
    default void onExpiredInput(TaskInfo task, String key, long ageNs, long maxAgeNs, long nowNs) {
    }

    /**
     * A cycle threw.
     *
     * @param task the task
     * @param error what was thrown
     * @param policy the policy now applied
     * @param nowNs world time
     */
    default void onTaskError(TaskInfo task, Throwable error, io.rtaware.core.task.ErrorPolicy policy, long nowNs) {
    }

    /**
     * A task changed state.
     *
     * @param task the task
     * @param state the new state
     * @param nowNs world time
     */
    default void onStateChange(TaskInfo task, TaskState state, long nowNs) {
    }

    /**
     * A cycle completed (successfully or not).
     *
     * @param task the task
     * @param releaseNs the scheduled release (the start, for continuous tasks)
     * @param startNs cycle start
     * @param endNs cycle end
     */
    default void onCycle(TaskInfo task, long releaseNs, long startNs, long endNs) {
    }

    /**
     * A produced value was committed to the store.
     *
     * @param producer the producing task
     * @param keyIndex dense index of the key (see {@link Monitor#keyNames()})
     * @param generation the new generation
     * @param nowNs commit time
     */
    default void onCommit(TaskInfo producer, int keyIndex, long generation, long nowNs) {
    }

    /**
     * An adaptive task's period changed (only with adaptive periods enabled). Called on the
     * task's thread between cycles; rare (at most once per evaluation window).
     *
     * @param task the task
     * @param change the change and the evidence behind it
     * @param nowNs world time of the decision (the end of the window's last cycle)
     */
    default void onPeriodChange(TaskInfo task, PeriodChange change, long nowNs) {
    }

    /**
     * The value just committed, right after {@link #onCommit}, on the producer's thread: the
     * producer's own buffer, which it does not touch until the call returns. Valid only during
     * the call: copy what you keep (without allocating, {@code copyFrom} into a buffer of your
     * own). Same rules as {@link #onCommit}: fast, no blocking, no allocation.
     *
     * @param producer the producing task
     * @param keyIndex dense index of the key (see {@link Monitor#keys()})
     * @param generation the new generation
     * @param nowNs commit time
     * @param value the committed value
     */
    default void onCommitValue(TaskInfo producer, int keyIndex, long generation, long nowNs,
                               io.rtaware.core.data.StateValue<?> value) {
    }

    /**
     * The record of a finished cycle, after {@link #onCycle} (and {@link #onTaskError} for a
     * cycle that threw), on the task's thread: how it ended and the generation each input held
     * during the cycle, in the order of {@link TaskInfo#inputKeys()} (0: never written). The array
     * is the task's own and is reused: read it during the call only. Fast, no blocking, no
     * allocation.
     *
     * @param task the task
     * @param outcome how the cycle ended
     * @param releaseNs the scheduled release (the start, for continuous tasks)
     * @param startNs cycle start
     * @param endNs cycle end
     * @param inputGenerations generation of each input read
     */
    default void onCycleRecord(TaskInfo task, CycleOutcome outcome, long releaseNs, long startNs, long endNs,
                               long[] inputGenerations) {
    }
}
