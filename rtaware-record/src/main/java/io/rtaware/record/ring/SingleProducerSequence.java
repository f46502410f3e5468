package io.rtaware.record.ring;

import java.util.concurrent.atomic.AtomicLong;

/**
 * The positions of a ring of {@code capacity} slots with <b>one producer thread at a time</b> and
 * one consumer thread: the producer claims the next position, writes the slot and publishes it;
 * the consumer reads the published positions and hands them back. Two threads producing at once
 * corrupt the ring: a caller whose producers may overlap needs a
 * {@link MultiProducerSequence}. Positions only grow; nothing locks or allocates.
 */
public final class SingleProducerSequence {

    private final AtomicLong head = new AtomicLong();
    private final AtomicLong tail = new AtomicLong();
    private final int capacity;

    /** @param capacity the ring's slots, at least 1 */
    public SingleProducerSequence(int capacity) {
        if (capacity < 1) {
            throw new IllegalArgumentException("ring capacity must be at least 1, got " + capacity);
        }
        this.capacity = capacity;
    }

    /**
     * Producer: the next position to write.
     *
     * @return the position, or -1 when every slot still holds an unread record
     */
    public long claim() {
        long h = head.get();
        return h - tail.get() >= capacity ? -1 : h;
    }

    /**
     * Producer: the slot at {@code position} is written and may be read.
     *
     * @param position what {@link #claim()} returned
     */
    public void publish(long position) {
        head.lazySet(position + 1);
    }

    /**
     * @param position a position
     * @return its slot index
     */
    public int slot(long position) {
        return (int) (position % capacity);
    }

    /** @return consumer: the first position not yet read */
    public long consumed() {
        return tail.get();
    }

    /** @return consumer: one past the last position published */
    public long published() {
        return head.get();
    }

    /**
     * Consumer: the positions before {@code position} are read and their slots free.
     *
     * @param position one past the last position read
     */
    public void consumedUpTo(long position) {
        tail.lazySet(position);
    }

    /** Consumer: drops every published position unread. */
    public void discardAll() {
        tail.lazySet(head.get());
    }
}
