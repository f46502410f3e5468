package io.rtaware.core.monitor;

/**
 * A binary min-heap of task slots (0..capacity-1) ordered by a key per slot, ties by the lower
 * slot (registration order): the pooled executor's timer structure. Arrays only, sized once:
 * pushing and popping never allocate. Not thread-safe (the pool's lock guards it).
 */
final class TaskHeap {

    private final int[] heap;
    private final long[] keys;
    private int size;

    /** @param capacity the number of slots */
    TaskHeap(int capacity) {
        heap = new int[capacity];
        keys = new long[capacity];
    }

    int size() {
        return size;
    }

    /** @return the smallest key, or {@link Long#MAX_VALUE} if empty */
    long peekKey() {
        return size == 0 ? Long.MAX_VALUE : keys[heap[0]];
    }

    /** @return the slot with the smallest key; only when not empty */
    int peek() {
        return heap[0];
    }

    /**
     * @param slot a slot not in the heap
     * @param key its key
     */
    void push(int slot, long key) {
        keys[slot] = key;
        int i = size++;
        while (i > 0) {
            int parent = (i - 1) >>> 1;
            if (!less(slot, heap[parent])) {
                break;
            }
            heap[i] = heap[parent];
            i = parent;
        }
        heap[i] = slot;
    }

    /** @return the slot with the smallest key, removed; only when not empty */
    int pop() {
        int top = heap[0];
        int last = heap[--size];
        int i = 0;
        int half = size >>> 1;
        while (i < half) {
            int child = 2 * i + 1;
            int right = child + 1;
            if (right < size && less(heap[right], heap[child])) {
                child = right;
            }
            if (!less(heap[child], last)) {
                break;
            }
            heap[i] = heap[child];
            i = child;
        }
        heap[i] = last;
        return top;
    }

    private boolean less(int a, int b) {
        long ka = keys[a];
        long kb = keys[b];
        return ka < kb || (ka == kb && a < b);
    }
}
