package io.rtaware.core.data;

/**
 * A task's view of one consumed key: a buffer the task owns, refreshed by the framework at the
 * start of every cycle, with what the refresh found. Obtained during initialization from
 * {@link io.rtaware.core.task.TaskSetup#consume}; used only by the owning task's thread.
 *
 * <p>The task must treat {@link #value()} as read-only: the framework copies into it only when
 * the producer committed a newer generation.
 *
 * @param <T> the value type
 */
public interface Input<T extends StateValue<T>> {

    /** @return the key this input reads */
    Key<T> key();

    /** @return this task's copy of the newest committed value (the empty value if NONE) */
    T value();

    /** @return NEW, OLD or NONE, as found by the copy at the start of this cycle */
    ReadStatus status();

    /** @return true if the status is NEW */
    default boolean isNew() {
        return status() == ReadStatus.NEW;
    }

    /** @return true if the producer has committed at least once */
    default boolean hasValue() {
        return status() != ReadStatus.NONE;
    }

    /**
     * @return world-time age of the value at the start of this cycle in nanoseconds (cycle start
     *     minus commit time), or {@link Long#MAX_VALUE} if NONE
     */
    long ageNs();

    /** @return the producer's commit counter for the copied value; 0 if NONE */
    long generation();

    /**
     * @return the maximum age declared for this input, or {@link Long#MAX_VALUE} if none was
     *     declared
     */
    long maxAgeNs();

    /**
     * @return true if a maximum age was declared and the copied value is older than it (or was
     *     never written)
     */
    default boolean isExpired() {
        return maxAgeNs() != Long.MAX_VALUE && ageNs() > maxAgeNs();
    }
}
