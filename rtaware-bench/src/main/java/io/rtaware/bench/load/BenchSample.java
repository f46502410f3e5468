package io.rtaware.bench.load;

import io.rtaware.core.data.StateValue;

/** The value a bench task produces each cycle: a sequence number. Mutable buffer; not thread-safe. */
public final class BenchSample implements StateValue<BenchSample> {

    /** cycles the producer has completed. */
    public long sequence;

    @Override
    public void copyFrom(BenchSample source) {
        sequence = source.sequence;
    }
}
