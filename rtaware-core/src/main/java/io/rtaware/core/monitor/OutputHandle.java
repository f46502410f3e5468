package io.rtaware.core.monitor;

import io.rtaware.core.data.Key;
import io.rtaware.core.data.Output;
import io.rtaware.core.data.StateValue;
import io.rtaware.core.data.StateVariable;

/** A producer's output: its own buffer and the publish mark. Task-thread only. */
final class OutputHandle<T extends StateValue<T>> implements Output<T> {

    private final Key<T> key;
    private final T buffer;
    private StateVariable<T> variable;
    private int keyIndex;
    private boolean marked;
    private long commits;

    OutputHandle(Key<T> key) {
        this.key = key;
        this.buffer = key.newBuffer();
    }

    @SuppressWarnings("unchecked")
    void bind(StateVariable<?> target, int index) {
        this.variable = (StateVariable<T>) target;
        this.keyIndex = index;
    }

    int keyIndex() {
        return keyIndex;
    }

    /** Commits if published this cycle; returns the new generation, or 0 if nothing was committed. */
    long commitIfMarked(long nowNs) {
        if (!marked) {
            return 0;
        }
        marked = false;
        variable.commit(buffer, nowNs);
        commits++;
        return variable.generation();
    }

    void discard() {
        marked = false;
    }

    @Override
    public Key<T> key() {
        return key;
    }

    @Override
    public T value() {
        return buffer;
    }

    @Override
    public void publish() {
        marked = true;
    }

    @Override
    public long commits() {
        return commits;
    }
}
