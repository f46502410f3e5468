package io.rtaware.core.monitor;

import io.rtaware.core.data.Input;
import io.rtaware.core.data.Key;
import io.rtaware.core.data.ReadStatus;
import io.rtaware.core.data.StateValue;
import io.rtaware.core.data.StateVariable;

/** A consumer's input: its own buffer plus what the last copy-in found. Task-thread only. */
final class InputHandle<T extends StateValue<T>> implements Input<T> {

    private final Key<T> key;
    private final T buffer;
    private final long maxAgeNs;
    private final StateVariable.ReadCursor cursor = new StateVariable.ReadCursor();
    private StateVariable<T> variable;
    private ReadStatus status = ReadStatus.NONE;
    private long heldGeneration;
    private long ageNs = Long.MAX_VALUE;

    InputHandle(Key<T> key, long maxAgeNs) {
        this.key = key;
        this.buffer = key.newBuffer();
        this.maxAgeNs = maxAgeNs;
    }

    @SuppressWarnings("unchecked")
    void bind(StateVariable<?> source) {
        this.variable = (StateVariable<T>) source;
    }

    /** Copies the newest value in if it changed; returns true if it was NEW. */
    boolean refresh(long nowNs) {
        variable.copyTo(buffer, heldGeneration, cursor);
        long generation = cursor.generation();
        if (generation == 0) {
            status = ReadStatus.NONE;
            ageNs = Long.MAX_VALUE;
        } else {
            status = generation != heldGeneration ? ReadStatus.NEW : ReadStatus.OLD;
            ageNs = nowNs - cursor.commitTimeNs();
        }
        heldGeneration = generation;
        return status == ReadStatus.NEW;
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
    public ReadStatus status() {
        return status;
    }

    @Override
    public long ageNs() {
        return ageNs;
    }

    @Override
    public long generation() {
        return heldGeneration;
    }

    @Override
    public long maxAgeNs() {
        return maxAgeNs;
    }
}
