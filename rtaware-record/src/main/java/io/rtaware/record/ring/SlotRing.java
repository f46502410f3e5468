package io.rtaware.record.ring;

import java.io.IOException;
import java.util.Objects;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicLongArray;
import java.util.function.Consumer;
import java.util.function.IntFunction;

/**
 * A ring of preallocated slots, filled by producers and read in order by <b>one consumer
 * thread</b>; nothing locks or allocates. A producer {@link #claim()}s a position, fills its
 * {@link #slot}, and {@link #publish}es it; the consumer {@link #drain}s the published slots in
 * position order and so frees them. A full ring refuses the claim (the producer drops its record),
 * so a producer never waits for the consumer.
 *
 * <p>Who may produce is the type's contract, in its name: {@link SingleProducerRing} for one
 * producer thread at a time, {@link MultiProducerRing} for any number at once.
 *
 * @param <S> the slot type: a mutable record the producers fill and the consumer reads
 */
public abstract sealed class SlotRing<S> permits SingleProducerRing, MultiProducerRing {

    private final Object[] slots;
    /** The position last published in each slot ({@code -1}: none yet). */
    private final AtomicLongArray published;
    /** The first position not yet read: written by the consumer, read by the producers. */
    private final AtomicLong consumed = new AtomicLong();

    SlotRing(int capacity, IntFunction<? extends S> newSlot) {
        if (capacity < 1) {
            throw new IllegalArgumentException("ring capacity must be at least 1, got " + capacity);
        }
        Objects.requireNonNull(newSlot, "newSlot");
        slots = new Object[capacity];
        published = new AtomicLongArray(capacity);
        for (int i = 0; i < capacity; i++) {
            slots[i] = Objects.requireNonNull(newSlot.apply(i), "newSlot made no slot");
            published.set(i, -1);
        }
    }

    /**
     * Producer: claims the next free position.
     *
     * @return the position, or -1 when every slot still holds an unread record
     */
    public abstract long claim();

    /**
     * Producer: the slot at {@code position} is filled and may be read.
     *
     * @param position what {@link #claim()} returned
     */
    public abstract void publish(long position);

    /**
     * @param position a claimed position
     * @return its slot, to fill (producer, between claim and publish) or to read (consumer)
     */
    @SuppressWarnings("unchecked")
    public final S slot(long position) {
        return (S) slots[index(position)];
    }

    /** @return the ring's slots */
    public final int capacity() {
        return slots.length;
    }

    /**
     * Consumer: reads the published slots in position order, freeing each once read: those
     * claimed before the drain began, up to the first not yet published. A drain ends however
     * fast the producers go on, so a consumer of several rings visits each in turn.
     *
     * @param reader what to do with each slot
     * @param a the reader's first argument
     * @param b the reader's second argument
     * @param <A> the first argument's type
     * @param <B> the second argument's type
     * @return slots read
     * @throws IOException if the reader fails (that slot and those after it stay unread)
     */
    public final <A, B> int drain(SlotReader<? super S, ? super A, ? super B> reader, A a, B b) throws IOException {
        long next = consumed.get();
        long end = nextClaim();
        int read = 0;
        while (next < end && published.get(index(next)) == next) {
            reader.read(slot(next), next, a, b);
            next++;
            consumed.lazySet(next);
            read++;
        }
        return read;
    }

    /**
     * Consumer: frees every published slot unread (after the consumer's output failed, so the
     * producers go on dropping nothing but what does not fit).
     *
     * @param onFree given each slot before it is freed (e.g. to clear references it holds)
     * @return slots freed
     */
    public final int discard(Consumer<? super S> onFree) {
        long next = consumed.get();
        int freed = 0;
        while (published.get(index(next)) == next) {
            onFree.accept(slot(next));
            next++;
            consumed.lazySet(next);
            freed++;
        }
        return freed;
    }

    /** @return the position the next claim would take (what a drain reads up to) */
    abstract long nextClaim();

    /**
     * @param position a position
     * @return its slot index
     */
    final int index(long position) {
        return (int) (position % slots.length);
    }

    /** @return the first position not yet read (what the producers compare a claim with) */
    final long consumed() {
        return consumed.get();
    }

    /**
     * Marks the slot at {@code position} published (release semantics: the slot's fields, written
     * before, are seen by the consumer that sees the mark).
     *
     * @param position the position
     */
    final void markPublished(long position) {
        published.lazySet(index(position), position);
    }
}
