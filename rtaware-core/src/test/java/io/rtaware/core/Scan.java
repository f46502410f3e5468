package io.rtaware.core;

import io.rtaware.core.data.Key;
import io.rtaware.core.data.StateValue;

/** A test value shaped like a laser scan: 683 ranges and a stamp. */
public final class Scan implements StateValue<Scan> {

    public static final int RANGES = 683;

    public final float[] ranges = new float[RANGES];
    public long stampNs;

    @Override
    public void copyFrom(Scan source) {
        System.arraycopy(source.ranges, 0, ranges, 0, RANGES);
        stampNs = source.stampNs;
    }

    public static Key<Scan> key(String name) {
        return Key.of(name, Scan.class, Scan::new);
    }
}
