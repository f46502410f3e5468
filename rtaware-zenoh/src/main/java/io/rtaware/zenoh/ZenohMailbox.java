package io.rtaware.zenoh;

import java.util.ArrayList;
import java.util.List;

/**
 * Where subscribers deliver samples: a bounded queue on the native side, filled by Zenoh's
 * threads and emptied by one reader thread with {@link #take}, which copies the next sample into
 * the reader's {@link SampleBuffer}. When the reader falls behind, the oldest samples are
 * dropped and counted ({@link #overflowed()}). Each subscriber tags its samples with a channel
 * number, so one reader can serve several topics.
 *
 * <p>One reader thread calls {@link #take}; {@link #subscribe} and {@link #close} may be called
 * from any thread, also while the reader waits: a reader waiting in {@code take} then returns
 * {@link Take#CLOSED}, and a later {@code take} throws.
 */
public final class ZenohMailbox implements AutoCloseable {

    /** What {@link #take} found. */
    public enum Take {
        /** a sample was copied into the buffer */
        SAMPLE,
        /** nothing arrived in time */
        TIMEOUT,
        /** a sample was bigger than the buffer: dropped; its lengths are in the buffer */
        TOO_LARGE,
        /** the mailbox is closed */
        CLOSED
    }

    private final ZenohSession session;
    private final List<Long> subscribers = new ArrayList<>();
    private volatile long handle;

    ZenohMailbox(ZenohSession session, long handle) {
        this.session = session;
        this.handle = handle;
    }

    /**
     * Subscribes to a key expression; its samples arrive here tagged with {@code channel}.
     *
     * @param key key expression (wildcards allowed)
     * @param channel the tag, chosen by the caller
     * @throws ZenohException if the key is invalid or the mailbox or session is closed
     */
    public synchronized void subscribe(String key, int channel) throws ZenohException {
        subscribers.add(session.declareSubscriber(key, live(), channel));
    }

    /**
     * Waits up to {@code timeoutNs} for the next sample and copies it into {@code into}.
     * Allocates nothing on the Java heap.
     *
     * @param timeoutNs longest wait in nanoseconds of wall time (0: do not wait)
     * @param into where to copy
     * @return what was found ({@link Take#CLOSED} when the mailbox was closed while waiting)
     * @throws ZenohException if the mailbox was closed before the call
     */
    public Take take(long timeoutNs, SampleBuffer into) throws ZenohException {
        int r = NativeZenoh.take(live(), timeoutNs, into.payload(), into.attachment(), into.info());
        return switch (r) {
            case 1 -> Take.SAMPLE;
            case 0 -> Take.TIMEOUT;
            case -1 -> Take.TOO_LARGE;
            default -> Take.CLOSED;
        };
    }

    /**
     * @return samples dropped so far because the reader fell behind
     * @throws ZenohException if the mailbox is closed
     */
    public long overflowed() throws ZenohException {
        return NativeZenoh.overflowed(live());
    }

    private long live() throws ZenohException {
        if (handle == 0) {
            throw new ZenohException("the Zenoh mailbox is closed");
        }
        return handle;
    }

    /**
     * Undeclares the subscribers, then closes the queue, waking a waiting reader. Idempotent;
     * safe from any thread (the native queue is freed only after the last call using it returns).
     */
    @Override
    public synchronized void close() throws ZenohException {
        if (handle == 0) {
            return;
        }
        ZenohException first = null;
        for (long s : subscribers) {
            try {
                NativeZenoh.undeclareSubscriber(s);
            } catch (ZenohException e) {
                first = first == null ? e : first;
            }
        }
        subscribers.clear();
        long h = handle;
        handle = 0;
        session.forget(this);
        NativeZenoh.closeMailbox(h);
        if (first != null) {
            throw first;
        }
    }
}
