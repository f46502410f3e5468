package io.rtaware.record;

import java.io.IOException;
import java.util.function.LongSupplier;

/**
 * Puts the writer thread's messages in log-time order through a bounded reorder window before
 * they go on: into the file (within and across chunks), or to a live {@link RecordingTap}. A
 * message is held until a message {@code windowNs} of world time newer has arrived (or the
 * window's message or byte budget is full), then passed on with every held message older than
 * it. The rings are drained one after another, so a message can arrive after a later one of
 * another ring (on {@code /tf}, odometry's transforms and the ground truth's); within the window
 * that is put right. A message that arrives after a newer one was already passed on falls
 * outside the window: the file's sink writes it all the same (nothing is lost) and counts it
 * ({@link #outOfOrder()}, reported with the recording), never silently misordered; a tap's sink
 * drops it (a viewer's transforms must not go back in time), so a tap gets every channel in
 * log-time order.
 *
 * <p>Log times passed on are the world time plus {@code logTimeOffsetNs} (the Unix-epoch time
 * of world time 0), publish times likewise. With {@link ClockTicks}, the {@code /clock} ticks
 * due up to each message are written just before it. With a {@link #holdAfter} limit (the end of
 * the {@code /statistics} window still to be published), nothing later than the limit is passed
 * on until the limit moves on, unless the window's message or byte budget is full. Writer thread
 * only; once its slots have grown to the run's message sizes it allocates nothing.
 */
final class LogTimeOrderedSink implements MessageSink {

    /** Where ordered messages go, with Unix-epoch log and publish times. */
    private final MessageSink out;
    /** Whether a message outside the window is dropped (a tap) rather than written late (a file). */
    private final boolean dropLate;
    private final long offsetNs;
    private final long windowNs;
    private final long budgetBytes;
    private final long[] time;
    private final long[] publish;
    private final long[] sequence;
    private final long[] arrival;
    private final int[] channel;
    private final int[] length;
    private final byte[][] data;
    /** A binary min-heap of slots, by (log time, arrival). */
    private final int[] heap;
    private int size;
    /** Free slots, a stack: the slots used last (already grown) are used again first. */
    private final int[] free;
    private int freeCount;
    private long heldBytes;
    private long arrivals;
    private long newestNs = Long.MIN_VALUE;
    private long lastWrittenNs = Long.MIN_VALUE;
    private long outOfOrder;
    /** {@code /clock}, or null when the world runs on wall time. */
    private ClockTicks clock;
    /** The latest log time that may be written now (world time), or null for no limit. */
    private LongSupplier limit;

    /**
     * @param out where ordered messages go (the file's writer, or a tap), their times Unix-epoch
     * @param dropLate true to drop a message that comes after a newer one was passed on (a tap),
     *     false to pass it on late (a file, which loses nothing)
     * @param logTimeOffsetNs added to every world time to make the log time passed on
     * @param windowNs world time a message is held for later, earlier messages
     * @param slots most messages held at once
     * @param budgetBytes most message bytes held at once
     */
    LogTimeOrderedSink(MessageSink out, boolean dropLate, long logTimeOffsetNs, long windowNs, int slots,
                       long budgetBytes) {
        this.out = out;
        this.dropLate = dropLate;
        this.offsetNs = logTimeOffsetNs;
        this.windowNs = windowNs;
        this.budgetBytes = budgetBytes;
        time = new long[slots];
        publish = new long[slots];
        sequence = new long[slots];
        arrival = new long[slots];
        channel = new int[slots];
        length = new int[slots];
        data = new byte[slots][];
        heap = new int[slots];
        free = new int[slots];
        for (int i = 0; i < slots; i++) {
            free[i] = slots - 1 - i;
        }
        freeCount = slots;
    }

    @Override
    public void write(int channelId, long seq, long logTimeNs, long publishTimeNs, byte[] bytes, int offset, int n)
            throws IOException {
        while (freeCount == 0 || (size > 0 && heldBytes + n > budgetBytes)) {
            writeOldest();
        }
        int slot = free[--freeCount];
        byte[] buffer = data[slot];
        if (buffer == null || buffer.length < n) {
            buffer = new byte[Math.max(n, buffer == null ? 64 : buffer.length * 2)];
            data[slot] = buffer;
        }
        System.arraycopy(bytes, offset, buffer, 0, n);
        time[slot] = logTimeNs;
        publish[slot] = publishTimeNs;
        sequence[slot] = seq;
        channel[slot] = channelId;
        length[slot] = n;
        arrival[slot] = arrivals++;
        heldBytes += n;
        push(slot);
        newestNs = Math.max(newestNs, logTimeNs);
        long until = limit == null ? newestNs - windowNs : Math.min(newestNs - windowNs, limit.getAsLong());
        while (size > 0 && time[heap[0]] <= until) {
            writeOldest();
        }
    }

    /**
     * Holds back every message whose log time is later than what {@code limitNs} says (world
     * time), for messages still to come with that log time (a {@code /statistics} window not yet
     * published). Call before the first {@link #write}.
     *
     * @param limitNs the latest log time that may be written now; read on every write
     */
    void holdAfter(LongSupplier limitNs) {
        limit = limitNs;
    }

    /**
     * Writes the {@code /clock} ticks due up to each message just before it. Call before the
     * first {@link #write}.
     *
     * @param ticks the ticks
     */
    void clock(ClockTicks ticks) {
        clock = ticks;
    }

    /**
     * Writes every held message, oldest first (at the end of the recording).
     *
     * @throws IOException if writing fails
     */
    void flush() throws IOException {
        while (size > 0) {
            writeOldest();
        }
    }

    /** @return messages that came after a message with a later log time was passed on (outside the window) */
    long outOfOrder() {
        return outOfOrder;
    }

    private void writeOldest() throws IOException {
        int slot = heap[0];
        size--;
        if (size > 0) {
            heap[0] = heap[size];
            siftDown(0);
        }
        free[freeCount++] = slot;
        heldBytes -= length[slot];
        long t = time[slot];
        if (t < lastWrittenNs) {
            outOfOrder++;
            if (dropLate) {
                return;
            }
        } else {
            lastWrittenNs = t;
            if (clock != null) {
                clock.upTo(t);
            }
        }
        out.write(channel[slot], sequence[slot], t + offsetNs, publish[slot] + offsetNs, data[slot], 0, length[slot]);
    }

    private boolean before(int a, int b) {
        return time[a] < time[b] || (time[a] == time[b] && arrival[a] < arrival[b]);
    }

    private void push(int slot) {
        int i = size++;
        heap[i] = slot;
        while (i > 0) {
            int parent = (i - 1) >>> 1;
            if (!before(heap[i], heap[parent])) {
                break;
            }
            swap(i, parent);
            i = parent;
        }
    }

    private void siftDown(int from) {
        int i = from;
        while (true) {
            int left = 2 * i + 1;
            if (left >= size) {
                return;
            }
            int smaller = left + 1 < size && before(heap[left + 1], heap[left]) ? left + 1 : left;
            if (!before(heap[smaller], heap[i])) {
                return;
            }
            swap(i, smaller);
            i = smaller;
        }
    }

    private void swap(int a, int b) {
        int t = heap[a];
        heap[a] = heap[b];
        heap[b] = t;
    }
}
