package io.rtaware.record.ring;

import java.io.IOException;

/**
 * The consumer's work on one published slot of a {@link SlotRing}, given two arguments of the
 * drain (e.g. where to write and the scratch buffers to encode with), so that a reader kept in a
 * field serves every drain without a capturing lambda.
 *
 * @param <S> the slot type
 * @param <A> the drain's first argument
 * @param <B> the drain's second argument
 */
@FunctionalInterface
public interface SlotReader<S, A, B> {

    /**
     * Reads one slot; the slot is freed when this returns.
     *
     * @param slot the slot (its fields as the producer left them)
     * @param position the slot's position: how many records were claimed before it
     * @param a the drain's first argument
     * @param b the drain's second argument
     * @throws IOException if the reader's output fails (the slot stays unread)
     */
    void read(S slot, long position, A a, B b) throws IOException;
}
