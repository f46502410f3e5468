package io.rtaware.record.ring;

import java.util.concurrent.atomic.AtomicLong;
import java.util.function.IntFunction;

/**
 * A {@link SlotRing} with <b>one producer thread at a time</b> (a key's producing task, a task's
 * thread, the ground-truth sampler) and one consumer thread. Two threads producing at once
 * corrupt the ring: producers that may overlap need a {@link MultiProducerRing}. A position
 * claimed and never published is claimed again by the next {@link #claim()}.
 *
 * @param <S> the slot type
 */
public final class SingleProducerRing<S> extends SlotRing<S> {

    /** The next position to claim: advanced by {@link #publish}. */
    private final AtomicLong next = new AtomicLong();

    /**
     * @param capacity the ring's slots, at least 1
     * @param newSlot makes each slot, given its index
     */
    public SingleProducerRing(int capacity, IntFunction<? extends S> newSlot) {
        super(capacity, newSlot);
    }

    @Override
    public long claim() {
        long position = next.get();
        return position - consumed() >= capacity() ? -1 : position;
    }

    @Override
    long nextClaim() {
        return next.get();
    }

    @Override
    public void publish(long position) {
        markPublished(position);
        next.lazySet(position + 1);
    }
}
