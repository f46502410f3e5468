package io.rtaware.record.ring;

import java.util.concurrent.atomic.AtomicLong;
import java.util.function.IntFunction;

/**
 * A {@link SlotRing} that <b>any number of threads</b> fill at once (the monitor's events, from
 * task threads and the watchdog), with one consumer thread: a producer claims its position by one
 * compare-and-set. A position claimed must be published, or the consumer stops at it.
 *
 * @param <S> the slot type
 */
public final class MultiProducerRing<S> extends SlotRing<S> {

    /** The next position to claim. */
    private final AtomicLong claimed = new AtomicLong();

    /**
     * @param capacity the ring's slots, at least 1
     * @param newSlot makes each slot, given its index
     */
    public MultiProducerRing(int capacity, IntFunction<? extends S> newSlot) {
        super(capacity, newSlot);
    }

    @Override
    public long claim() {
        long position;
        do {
            position = claimed.get();
            if (position - consumed() >= capacity()) {
                return -1;
            }
        } while (!claimed.compareAndSet(position, position + 1));
        return position;
    }

    @Override
    long nextClaim() {
        return claimed.get();
    }

    @Override
    public void publish(long position) {
        markPublished(position);
    }
}
