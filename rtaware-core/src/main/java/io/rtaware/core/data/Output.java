package io.rtaware.core.data;

/**
 * A task's view of one produced key: a buffer the task owns and writes into during its cycle.
 * After {@link #publish()} the framework commits the buffer to the store when the cycle ends,
 * under the key's write lock; a cycle that throws commits nothing. Used only by the owning
 * task's thread.
 *
 * @param <T> the value type
 */
public interface Output<T extends StateValue<T>> {

    /** @return the key this output writes */
    Key<T> key();

    /** @return the producer's buffer; write the next value here */
    T value();

    /** Marks the buffer for commit at the end of this cycle. */
    void publish();

    /**
     * @return how many times this output was committed so far
     */
    long commits();
}
