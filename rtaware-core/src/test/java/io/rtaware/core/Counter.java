package io.rtaware.core;

import io.rtaware.core.data.Key;
import io.rtaware.core.data.StateValue;

/** A test value: one long. */
public final class Counter implements StateValue<Counter> {

    public long value;

    @Override
    public void copyFrom(Counter source) {
        value = source.value;
    }

    public static Key<Counter> key(String name) {
        return Key.of(name, Counter.class, Counter::new);
    }
}
