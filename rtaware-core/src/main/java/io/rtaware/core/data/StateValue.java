package io.rtaware.core.data;

/**
 * A mutable value buffer that can be shared through the data store without allocating.
 *
 * <p>The store keeps one instance per key, each producer one it writes into, and each consumer
 * one it reads from; all of them are created once, at initialization, by the key's factory.
 * {@link #copyFrom(StateValue)} must copy the whole value (deeply: arrays are copied element by
 * element into arrays this instance already owns) and must not allocate. A value with a
 * variable number of elements keeps a fixed capacity and a count.
 *
 * <p>Implementations are not thread-safe; the store serializes access.
 *
 * @param <T> the implementing type itself
 */
public interface StateValue<T extends StateValue<T>> {

    /**
     * Replaces the contents of this value with a copy of {@code source}.
     *
     * @param source the value to copy; not modified
     */
    void copyFrom(T source);
}
