package ${package};

import io.rtaware.core.data.Key;
import io.rtaware.core.data.StateValue;

/**
 * One number that tasks share. Each task reads its own copy, filled by {@link #copyFrom}, never the
 * writer's object; the monitor allocates the copies once, so a cycle allocates nothing.
 */
public final class Quantity implements StateValue<Quantity> {
    /** The range to the nearest obstacle, metres: the sensor produces it, the guard reads it. */
    public static final Key<Quantity> NEAREST_M = Key.of("nearest_m", Quantity.class, Quantity::new);
    /** The speed the guard allows, m/s. */
    public static final Key<Quantity> SPEED_MPS = Key.of("speed_mps", Quantity.class, Quantity::new);

    /** The value, in the unit its key names. */
    public double value;

    @Override
    public void copyFrom(Quantity source) {
        value = source.value;
    }
}
