package io.rtaware.record.ring;

import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicLongArray;

/**
 * The positions of a ring of {@code capacity} slots that <b>any number of threads</b> fill at
 * once, read by one consumer thread: a producer claims a position by one compare-and-set, writes
 * the slot and marks it published; the consumer reads positions in order as their slots are
 * marked. Nothing locks or allocates.
 */
public final class MultiProducerSequence {

    private final int capacity;
    private final AtomicLongArray published;
    private final AtomicLong claimed = new AtomicLong();
    private final AtomicLong consumed = new AtomicLong();
    /** Consumer thread only: the next position to read. */
    private long next;

    /** @param capacity the ring's slots, at least 1 */
    public MultiProducerSequence(int capacity) {
        if (capacity < 1) {
            throw new IllegalArgumentException("ring capacity must be at least 1, got " + capacity);
        }
        this.capacity = capacity;
        published = new AtomicLongArray(capacity);
        for (int i = 0; i < capacity; i++) {
            published.set(i, -1);
        }
    }

    /**
     * Producer (any thread): claims the next free position.
     *
     * @return the position, or -1 when every slot still holds an unread record
     */
    public long claim() {
        long c;
        do {
            c = claimed.get();
            if (c - consumed.get() >= capacity) {
                return -1;
            }
        } while (!claimed.compareAndSet(c, c + 1));
        return c;
    }

    /**
     * Producer: the slot at {@code position} is written and may be read.
     *
     * @param position what {@link #claim()} returned
     */
    public void publish(long position) {
        published.set(slot(position), position);
    }

    /**
     * @param position a position
     * @return its slot index
     */
    public int slot(long position) {
        return (int) (position % capacity);
    }

    /** @return consumer: the next position to read, or -1 if it is not published yet */
    public long nextPublished() {
        return published.get(slot(next)) == next ? next : -1;
    }

    /** Consumer: the position {@link #nextPublished()} returned is read and its slot free. */
    public void consumedOne() {
        next++;
        consumed.lazySet(next);
    }
}
